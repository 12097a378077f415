#!/bin/bash
# An independent engine judged by `twinraster verify --coverage`: Debian's f3d (VTK's glTF importer,
# OpenGL on Mesa's llvmpipe under Xvfb) draws each glTF file, and twinraster judges where its image
# is covered. Files with a camera are drawn through it (--camera-index 0); files without one through
# the camera twinraster frames them with (explain --json's camera matrix, mirrored back into
# glTF's right-handed frame). Every image single-sampled (f3d's FXAA is off unless asked), cleared
# to magenta (--bg-color 1,0,1, which is (255, 0, 255) in the PNG), at twinraster's canvas.
# Prints one line per file and exits 1 when any judgement is not "passed".
#
#   sudo apt-get install f3d xvfb xauth    # written for Debian 12's f3d 1.3.1; later ones not tried
#   bash scripts/check-f3d-coverage.sh [build/bin/twinraster] [OUT_DIR]
#
# Measured results and the one known false alarm (back faces culled) are in docs/verify.md,
# "An independent engine: f3d".
set -u
exe=${1:-build/bin/twinraster}
out=${2:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/.." && pwd)
models=/usr/share/assimp/models/glTF2
for tool in f3d xvfb-run python3; do
  command -v "$tool" >/dev/null || { echo "check-f3d-coverage: $tool is not installed" >&2; exit 2; }
done
[ -x "$exe" ] || { echo "check-f3d-coverage: no executable $exe (build first)" >&2; exit 2; }
mkdir -p "$out"

# f3d's camera options for twinraster's camera of a file without one; its canvas for any file.
camera_args() {
  "$exe" explain "$1" --json | python3 -c '
import json, math, sys
j = json.load(sys.stdin)
c = j["canvas"]
args = ["--resolution=%d,%d" % (c["width"], c["height"])]
if sys.argv[1] == "framed":
    m = j["camera_matrix"]  # rows: the camera axes right, up, forward; last column -axis.eye
    axes = [row[:3] for row in m[:3]]
    eye = [-sum(axes[i][k] * m[i][3] for i in range(3)) for k in range(3)]
    gltf = lambda v: (v[0], v[1], -v[2])  # the chapter mirrors glTF in z
    e, f, u = gltf(eye), gltf(axes[2]), gltf(axes[1])
    v = j["viewport"]
    args += ["--camera-position=%r,%r,%r" % e, "--camera-focal-point=%r,%r,%r" % tuple(e[i] + f[i] for i in range(3)),
             "--camera-view-up=%r,%r,%r" % u,
             "--camera-view-angle=%r" % math.degrees(2 * math.atan(v["height"] / 2 / v["distance"]))]
else:
    args.append("--camera-index=0")
print(" ".join(args))' "$2"
}

failed=0
judge() {  # judge FILE file|framed
  local name
  name=$(basename "${1%.*}")
  local png="$out/$name.png"
  # shellcheck disable=SC2046  # the arguments are words without spaces
  timeout 120 xvfb-run -a -s "-screen 0 2048x2048x24" f3d --dry-run --quiet --output="$png" \
    $(camera_args "$1" "$2") --bg-color=1,0,1 "$1" || { echo "$name: f3d failed"; failed=1; return; }
  local verdict
  verdict=$("$exe" verify --coverage "$1" "$png" --background 255,0,255 --no-map --json | python3 -c '
import json, sys
j = json.load(sys.stdin)
p = j["pixels"]
print("%s: %d certainly covered, %d spills, %d holes" % (j["verdict"], p["certainly_covered"], p["spills"], p["holes"]))')
  echo "$name ($2 camera): $verdict"
  [[ $verdict == passed:* ]] || failed=1
}

for f in "$root"/scenes/gltf/*.gltf "$root"/scenes/gltf/*.glb; do judge "$f" file; done
judge "$models/cameras/Cameras.gltf" file
judge "$models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" file
for n in 04 05 06 11 12 13 14 15; do
  judge "$models/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_$n.gltf" framed
done
echo "images in $out"
exit $failed
