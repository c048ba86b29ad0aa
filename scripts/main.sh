#!/usr/bin/env bash
# The main job, end to end: install dependencies, build Kiln (which compiles the shipped materials
# into a variant pack), describe that pack, and parse the lecture's shaders.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release

echo
echo "== kiln variants materials/*.shader"
build/release/bin/kiln variants materials/*.shader
echo
echo "== kiln compile materials/*.shader -o build/release/materials/materials.kpack --all-features"
build/release/bin/kiln compile materials/*.shader -o build/release/materials/materials.kpack --all-features \
    --cache-dir build/release/kiln-cache --stats
build/release/bin/kiln info build/release/materials/materials.kpack
echo
echo "== kiln validate: one material instance per shipped shader"
build/release/bin/kiln validate --pack build/release/materials/materials.kpack materials/*.material
echo "all $(ls materials/*.material | wc -l) material instances validate"
echo
echo "== the lecture's shaders (tests/lecture), compiled with Kiln's templates"
echo "   Lectures 01-05 print \`float4 lightColor = _LightColor0.rgb;\` (05 also a float4 albedo"
echo "   from .rgb): Kiln must report that type error, which the test suite asserts before it"
echo "   compiles the corrected text. Any other outcome fails this job."
lecture_out=$(mktemp -d)
trap 'rm -rf "$lecture_out"' EXIT
for f in tests/lecture/*.shader; do
    expect_error=false
    case "$(basename "$f")" in 0[1-5]_*) expect_error=true ;; esac
    if message=$(build/release/bin/kiln --color=never compile "$f" -I tests/lecture \
                     -o "$lecture_out/lecture.kpack" 2>&1); then
        $expect_error && { echo "  UNEXPECTED: $f compiled; its printed type error is gone"; exit 1; }
        echo "  ok                          $f"
    else
        $expect_error || { echo "  UNEXPECTED error in $f:"; echo "$message"; exit 1; }
        echo "  expected lecture type error $f: $(echo "$message" | head -1 | sed 's/^.*error: //')"
    fi
done
echo
echo "== kiln render: the demo scene (scenes/demo), soft shadows, headless, validation layer on"
mkdir -p out
build/release/bin/kiln render scenes/demo/demo.gltf --validation --width 1280 --height 720 \
    --shadows soft \
    -o out/demo.png --exr out/demo.exr
echo
echo "== kiln render: the glTF samples in ../shared/gltf-samples"
if [ -d ../shared/gltf-samples ]; then
    for s in Box BoxTextured TextureCoordinateTest TextureEncodingTest \
             MetalRoughSpheresNoTextures NormalTangentTest LightsPunctualLamp; do
        build/release/bin/kiln render "../shared/gltf-samples/$s/glTF/$s.gltf" --validation \
            --width 640 --height 480 -o "out/$s.png" 2>/dev/null
    done
else
    echo "  ../shared/gltf-samples is absent: samples skipped"
fi
echo "images in out/"
