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
    expected="pass ForwardBase variant FOG_LINEAR: "
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
