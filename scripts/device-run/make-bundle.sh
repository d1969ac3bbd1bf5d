#!/bin/bash
# Builds what a lent GPU machine runs (docs/devices.md, "How the run was made"):
# prism at HEAD without OpenImageIO (oiio_free.py), its tests and benchmark, and
# the libraries they need, in build-gpu/ (about 42 MB), for `device run` with
# carry ["build-gpu"] and the command `bash build-gpu/gpu-run.sh`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
src=/tmp/prism-device-src   # the binaries name it (PRISM_SOURCE_DIR); gpu-run.sh links it there
build="$root/build-dev"     # likewise (PRISM_BINARY_DIR)
out="$root/build-gpu"
sys=/lib/x86_64-linux-gnu

git -C "$root" worktree remove --force "$src" 2>/dev/null || rm -rf "$src"
git -C "$root" worktree prune
git -C "$root" worktree add --detach "$src" HEAD
python3 "$root/scripts/device-run/oiio_free.py" "$src"
grep -qs "CMAKE_HOME_DIRECTORY:INTERNAL=$src\$" "$build/CMakeCache.txt" || rm -rf "$build"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPRISM_MPI=OFF
make -C "$build" -j"$(nproc)" prism_cli prism_bench device_tests render_tests kernel_tests accel_tests host_tests \
  plugin_tests c_api_test c_api_arguments_test c_api_scene_test c_api_threads_test obj_plugin off_plugin ply_plugin \
  stl_example_plugin bad_abi_fixture no_entry_fixture unresolved_fixture

rm -rf "$out"
mkdir -p "$out/benchmarks" "$out/tests" "$out/plugins" "$out/devlib/std" "$out/data/bunny"
cp -a "$build/prism" "$build"/libprism.so* "$build/plugin-fixtures" "$out/"
rm -rf "$out/plugin-fixtures/CMakeFiles"
cp "$build"/plugins/*.so "$out/plugins/"
cp "$build/benchmarks/prism-bench" "$out/benchmarks/"
cp "$build"/tests/*_tests "$build"/tests/c_api_*test "$out/tests/"
for lib in libOpenCL.so.1 libOpenMeshCore.so.9.0 libgmp.so.10 libtbb.so.12 libtinyobjloader.so.2rc10 \
           libpng16.so.16 libz.so.1; do
  cp -L "$sys/$lib" "$out/devlib/"
done
cp -L "$sys/libstdc++.so.6" "$sys/libgcc_s.so.1" "$out/devlib/std/"  # used only where the machine's are older
tar -cJhf "$out/devlib/extra-libs.tar.xz" -C "$sys" libembree3.so.3   # 44 MB, 9 MB packed
bunny="$root/../shared/data/meshes/bunny/bun_zipper.ply"
if [ -f "$bunny" ]; then cp "$bunny" "$out/data/bunny/"; else echo "make-bundle.sh: no $bunny: the bench phase will fail" >&2; fi
cp "$root/scripts/device-run/gpu-run.sh" "$out/"
echo "$root" > "$out/origin.txt"
du -sh "$out"
