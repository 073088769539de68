// Material textures: RGBA8 or RGBA16 texels, decoded from sRGB for colour uses and read as they are for data (metallic-
// roughness, normals), filtered bilinearly (or by the nearest texel, glTF's magFilter NEAREST) with glTF's wrap
// modes, at the use's UV set through its KHR_texture_transform. Compute kernels have no derivatives for mip
// selection, so there is no mipmapping; jittered supersampling averages the texture over each pixel instead.
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

vec4 fetchTexel(TextureRecord texture, int x, int y, bool srgb) {
  const int wx = wrapTexel(x, int(texture.width), texture.wrap & 3u);
  const int wy = wrapTexel(y, int(texture.height), (texture.wrap >> 2u) & 3u);
  const uint at = uint(wy) * texture.width + uint(wx);
  const vec4 texel = (texture.wrap & kTexels16) != 0u
                         ? vec4(unpackUnorm2x16(texels[texture.firstTexel + 2u * at]),
                                unpackUnorm2x16(texels[texture.firstTexel + 2u * at + 1u]))
                         : unpackUnorm4x8(texels[texture.firstTexel + at]);
  return srgb ? vec4(srgbToLinear(texel.rgb), texel.a) : texel;  // decode before filtering: sRGB values do not average
}

// RGB (and alpha) of texture `index` at uv (glTF convention: v grows downwards from the top row), linear:
// decoded from sRGB when `srgb`.
vec4 sampleTexture(uint index, vec2 uv, bool srgb) {
  const TextureRecord texture = textures[index];
  // Far-off or broken UVs must not overflow the int conversion; 2^20 texels is beyond any texture's period.
  const vec2 safeUv = any(isnan(uv)) ? vec2(0.0) : uv;
  const vec2 position = clamp(safeUv * vec2(texture.width, texture.height), vec2(-1048576.0), vec2(1048576.0));
  if ((texture.wrap & kFilterNearest) != 0u) {
    return fetchTexel(texture, int(floor(position.x)), int(floor(position.y)), srgb);
  }
  const vec2 centred = position - 0.5;
  const vec2 cell = floor(centred);
  const vec2 f = centred - cell;
  const int x = int(cell.x), y = int(cell.y);
  return mix(mix(fetchTexel(texture, x, y, srgb), fetchTexel(texture, x + 1, y, srgb), f.x),
             mix(fetchTexel(texture, x, y + 1, srgb), fetchTexel(texture, x + 1, y + 1, srgb), f.x), f.y);
}

// The UV a use of a texture reads: its UV set through its KHR_texture_transform.
vec2 textureUv(TextureRef ref, vec2 uv0, vec2 uv1) {
  const vec3 uv = vec3(ref.texCoord == 1u ? uv1 : uv0, 1.0);
  return vec2(dot(ref.row0, uv), dot(ref.row1, uv));
}

vec4 sampleTextureRef(TextureRef ref, vec2 uv0, vec2 uv1, bool srgb) {
  return sampleTexture(uint(ref.texture), textureUv(ref, uv0, uv1), srgb);
}

#endif
