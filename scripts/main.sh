#!/usr/bin/env bash
# The main job, end to end: install dependencies, build Kiln (which compiles the shipped materials
# into a variant pack), describe that pack, and parse the lecture's shaders.
set -euo pipefail
cd "$(dirname "$0")/.."

# The images this job promises (README): it fails unless each is in out/ and decodes as its format.
samples=(Box BoxTextured TextureCoordinateTest TextureEncodingTest MetalRoughSpheresNoTextures
         NormalTangentTest LightsPunctualLamp)
images=(out/demo.png out/demo.exr out/demo-deferred.png)
if [ -d ../shared/gltf-samples ]; then
    for s in "${samples[@]}"; do images+=("out/$s.png"); done
fi

bash scripts/setup.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release

echo
echo "== kiln variants materials/*.shader"
build/release/bin/kiln variants materials/*.shader
echo
# The same shaders the build compiles (materials/CMakeLists.txt), internal ones included: the
# renderer's deferred and shadow passes need Hidden/Internal-DeferredShading and
# Hidden/Internal-ScreenSpaceShadows from this pack. Through the build's cache this is a rebuild
# with nothing to compile.
echo "== kiln compile materials/*.shader materials/internal/*.shader -o build/release/materials/materials.kpack --all-features"
build/release/bin/kiln compile materials/*.shader materials/internal/*.shader \
    -o build/release/materials/materials.kpack --all-features \
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
rm -rf out
mkdir -p out
build/release/bin/kiln render scenes/demo/demo.gltf --validation --width 1280 --height 720 \
    --shadows soft \
    -o out/demo.png --exr out/demo.exr
echo
echo "== kiln render: the same scene on the deferred path, its light pass shadowed"
build/release/bin/kiln render scenes/demo/demo.gltf --validation --width 1280 --height 720 \
    --path deferred --shadows soft -o out/demo-deferred.png
echo
echo "== kiln render: the glTF samples in ../shared/gltf-samples"
if [ -d ../shared/gltf-samples ]; then
    for s in "${samples[@]}"; do
        build/release/bin/kiln render "../shared/gltf-samples/$s/glTF/$s.gltf" --validation \
            --width 640 --height 480 -o "out/$s.png"
    done
else
    echo "  ../shared/gltf-samples is absent: samples skipped"
fi
echo
echo "== the images in out/"
for f in "${images[@]}"; do
    [ -s "$f" ] || { echo "  MISSING: $f"; exit 1; }
    case "$f" in
        *.png) magic=$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n'); want=89504e470d0a1a0a ;;
        *.exr) magic=$(head -c 4 "$f" | od -An -tx1 | tr -d ' \n'); want=762f3101 ;;
    esac
    [ "$magic" = "$want" ] || { echo "  NOT AN IMAGE: $f"; exit 1; }
    echo "  $f ($(stat -c %s "$f") bytes)"
done
echo "main: ${#images[@]} images in out/"
