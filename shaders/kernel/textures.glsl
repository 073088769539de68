// Base-colour textures: bilinear filtering of RGBA8 sRGB texels with glTF's wrap modes. Compute kernels have
// no derivatives for mip selection, so there is no mipmapping; jittered supersampling averages the texture
// over each pixel instead.
#ifndef RAYLAB_KERNEL_TEXTURES_GLSL
#define RAYLAB_KERNEL_TEXTURES_GLSL

// IEC 61966-2-1 sRGB decoding.
vec3 srgbToLinear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

int wrapTexel(int i, int size, uint mode) {
  if (mode == kWrapClamp) return clamp(i, 0, size - 1);
  if (mode == kWrapMirror) {
    const int period = 2 * size;
    const int j = ((i % period) + period) % period;
    return j < size ? j : period - 1 - j;
  }
  return ((i % size) + size) % size;
}

vec4 fetchTexel(TextureRecord texture, int x, int y) {
  const int wx = wrapTexel(x, int(texture.width), texture.wrap & 3u);
  const int wy = wrapTexel(y, int(texture.height), (texture.wrap >> 2u) & 3u);
  const vec4 texel = unpackUnorm4x8(texels[texture.firstTexel + uint(wy) * texture.width + uint(wx)]);
  return vec4(srgbToLinear(texel.rgb), texel.a);  // decode before filtering: sRGB values do not average
}

// Linear RGB (and alpha) of texture `index` at uv (glTF convention: v grows downwards from the top row).
vec4 sampleTexture(uint index, vec2 uv) {
  const TextureRecord texture = textures[index];
  // Far-off or broken UVs must not overflow the int conversion; 2^20 texels is beyond any texture's period.
  const vec2 safeUv = any(isnan(uv)) ? vec2(0.0) : uv;
  const vec2 position = clamp(safeUv * vec2(texture.width, texture.height) - 0.5, vec2(-1048576.0), vec2(1048576.0));
  const vec2 cell = floor(position);
  const vec2 f = position - cell;
  const int x = int(cell.x), y = int(cell.y);
  return mix(mix(fetchTexel(texture, x, y), fetchTexel(texture, x + 1, y), f.x),
             mix(fetchTexel(texture, x, y + 1), fetchTexel(texture, x + 1, y + 1), f.x), f.y);
}

#endif
