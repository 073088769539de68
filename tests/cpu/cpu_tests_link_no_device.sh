#!/usr/bin/env bash
# The CPU tests link no device layer: no Vulkan loader, no GLFW, no Embree (shared libraries, by ldd) and no ImGui
# (Debian's libimgui.a is static, so by its symbols). Usage: cpu_tests_link_no_device.sh BINARY...
set -euo pipefail
status=0
for binary in "$@"; do
  libraries=$(ldd "$binary")
  for library in libvulkan libglfw libembree; do
    if grep -q "$library" <<<"$libraries"; then
      echo "$(basename "$binary") links $library: a CPU test must not need a device or a window" >&2
      status=1
    fi
  done
  if nm -C "$binary" | grep -q 'ImGui::'; then
    echo "$(basename "$binary") contains ImGui: a CPU test must not link the viewer" >&2
    status=1
  fi
done
[[ $status -eq 0 ]] && echo "$# CPU test binaries link no Vulkan, GLFW, Embree or ImGui"
exit $status
