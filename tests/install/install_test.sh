#!/bin/bash
# Installs Kiln from BUILD_DIR into a fresh prefix, then builds tests/install/consumer against it
# with Ninja and with Unix Makefiles, runs it, and checks that no installed file names BUILD_DIR.
# Usage: install_test.sh BUILD_DIR CONSUMER_SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
consumer=$(realpath "$2")
work=$(mktemp -d /tmp/kiln-install-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in bin/kiln bin/kiln-worker bin/kiln-render lib/cmake/Kiln/KilnConfig.cmake lib/cmake/Kiln/Kiln.cmake \
         include/kiln/pack/reader.h share/kiln/materials.kpack share/kiln/templates/UnityCG.cginc; do
    [ -e "$prefix/$f" ] || { echo "FAIL: $f was not installed"; exit 1; }
done

# A build machine's kiln needs no renderer libraries; kiln-render (kiln render) has them.
needed=$(readelf -d "$prefix/bin/kiln" | grep NEEDED || true)
if echo "$needed" | grep -Eq 'vulkan|OpenColorIO|tinygltf'; then
    echo "FAIL: bin/kiln links a renderer library:"; echo "$needed"; exit 1
fi
readelf -d "$prefix/bin/kiln-render" | grep -q 'libvulkan' ||
    { echo "FAIL: bin/kiln-render does not link the Vulkan loader"; exit 1; }

# Nothing installed may point back at the build folder (the prefix must be relocatable).
if grep -rlF "$build" "$prefix"; then
    echo "FAIL: the files above name the build folder $build"
    exit 1
fi

# What each component's config finds: traced, for the log, and checked for pack (an engine that
# only loads packs must not need Vulkan, OpenColorIO, tinygltf, glslang, SPIRV-Tools or
# SPIRV-Cross).
for component in pack material runtime compiler; do
    probe="$work/probe-$component"
    mkdir -p "$probe"
    printf 'cmake_minimum_required(VERSION 3.25)\nproject(P LANGUAGES CXX)\nfind_package(Kiln REQUIRED COMPONENTS %s)\n' \
        "$component" >"$probe/CMakeLists.txt"
    cmake -S "$probe" -B "$probe/build" -DCMAKE_PREFIX_PATH="$prefix" --trace-expand \
        >"$probe.log" 2>&1 || { cat "$probe.log"; echo "FAIL: COMPONENTS $component"; exit 1; }
    found=$(grep -F 'KilnConfig.cmake' "$probe.log" | grep -oE '(find_dependency|pkg_check_modules)\([A-Za-z_-]+' |
            sed -E 's/.*\(//' | sort -u | tr '\n' ' ')
    echo "COMPONENTS $component finds: $found"
    if [ "$component" = pack ] && [ "$found" != "PkgConfig XXHASH " ]; then
        echo "FAIL: the pack component finds more than xxhash: $found"; exit 1
    fi
done
# Unknown components are an error naming the valid ones.
printf 'cmake_minimum_required(VERSION 3.25)\nproject(P LANGUAGES CXX)\nfind_package(Kiln REQUIRED COMPONENTS packs)\n' \
    >"$work/probe-pack/CMakeLists.txt"
if cmake -S "$work/probe-pack" -B "$work/probe-pack/bad" -DCMAKE_PREFIX_PATH="$prefix" >"$work/bad.log" 2>&1; then
    echo "FAIL: COMPONENTS packs configured"; exit 1
fi
grep -q "unknown Kiln component 'packs'" "$work/bad.log" || { cat "$work/bad.log"; echo "FAIL: no message"; exit 1; }

# COMPONENTS pack on a view of this machine without the other components' packages: their CMake
# packages cannot be found and pkg-config sees only xxhash. Configure, build, run.
nopkg="$work/pkgconfig-xxhash-only"
mkdir -p "$nopkg"
ln -s "$(pkg-config --variable=pcfiledir libxxhash)/libxxhash.pc" "$nopkg/"
disable=()
for p in Vulkan TinyGLTF glm SPIRV-Tools SPIRV-Tools-opt glslang spirv_cross_core spirv_cross_glsl \
         spirv_cross_hlsl spirv_cross_msl OpenColorIO; do
    disable+=("-DCMAKE_DISABLE_FIND_PACKAGE_$p=TRUE")
done
dir="$work/consumer-pack-only"
env -u KILN_TEMPLATES_DIR -u KILN_WORKER PATH=/usr/bin:/bin PKG_CONFIG_LIBDIR="$nopkg" \
    cmake -S "$consumer" -B "$dir" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" -DKILN_COMPONENTS=pack \
    "${disable[@]}" >"$dir.log" 2>&1 || { cat "$dir.log"; echo "FAIL: configure COMPONENTS pack"; exit 1; }
cmake --build "$dir" >>"$dir.log" 2>&1 || { cat "$dir.log"; echo "FAIL: build COMPONENTS pack"; exit 1; }
out=$("$dir/pick_variant" "$dir/packs/nested/consumer.kpack")
echo "COMPONENTS pack: $out"
[[ "$out" == "pass ForwardBase variant HALF_TINT: "* ]] || { echo "FAIL: COMPONENTS pack output"; exit 1; }

# pkg-config from the prefix: the same loader compiled with nothing but kiln-pack's flags.
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
libs=$(pkg-config --libs kiln-pack)
echo "pkg-config --libs kiln-pack: $libs"
[[ "$libs" == *"-lkiln_pack"* && "$libs" == *"-lxxhash"* ]] || { echo "FAIL: kiln-pack.pc"; exit 1; }
for c in material runtime compiler; do
    pkg-config --exists "kiln-$c" || { echo "FAIL: kiln-$c.pc"; exit 1; }
done
# shellcheck disable=SC2046
c++ -std=c++20 -o "$work/pick_variant_pc" "$consumer/pick_variant.cpp" \
    $(pkg-config --cflags --libs kiln-pack) || { echo "FAIL: build with pkg-config"; exit 1; }
out=$("$work/pick_variant_pc" "$dir/packs/nested/consumer.kpack")
[[ "$out" == "pass ForwardBase variant HALF_TINT: "* ]] || { echo "FAIL: pkg-config build output"; exit 1; }
unset PKG_CONFIG_PATH

for gen in Ninja "Unix Makefiles"; do
    dir="$work/consumer-${gen// /-}"
    echo "== $gen"
    # PATH without the build tree: the consumer must not find a kiln except the installed one.
    env -u KILN_TEMPLATES_DIR -u KILN_WORKER PATH=/usr/bin:/bin \
        cmake -S "$consumer" -B "$dir" -G "$gen" -DCMAKE_PREFIX_PATH="$prefix" >"$dir.log" 2>&1 ||
        { cat "$dir.log"; echo "FAIL: configure with $gen"; exit 1; }
    env -u KILN_TEMPLATES_DIR -u KILN_WORKER PATH=/usr/bin:/bin \
        cmake --build "$dir" >>"$dir.log" 2>&1 ||
        { cat "$dir.log"; echo "FAIL: build with $gen"; exit 1; }
    pack="$dir/packs/nested/consumer.kpack"
    out=$("$dir/pick_variant" "$pack")
    echo "$out"
    expected="pass ForwardBase variant HALF_TINT: "
    [[ "$out" == "$expected"* && "$out" == *"(magic 07230203), alpha blend yes, zwrite off" ]] ||
        { echo "FAIL: unexpected output with $gen"; exit 1; }
    # An unchanged build does not run kiln; a newer kiln binary rebuilds the pack.
    before=$(stat -c %y "$pack")
    cmake --build "$dir" >>"$dir.log" 2>&1
    [ "$(stat -c %y "$pack")" == "$before" ] ||
        { echo "FAIL: a no-op build with $gen recompiled the pack"; exit 1; }
    sleep 1
    touch "$prefix/bin/kiln"
    cmake --build "$dir" >"$dir.rebuild.log" 2>&1
    grep -q "Compiling Kiln materials" "$dir.rebuild.log" ||
        { cat "$dir.rebuild.log"; echo "FAIL: a new kiln binary did not rebuild the pack ($gen)"; exit 1; }
done
echo "PASS"
