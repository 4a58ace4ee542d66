#!/usr/bin/env bash
# Installs ringid into a temporary prefix and builds, against the installed
# tree only, examples/ and the library snippet of README.md; runs both on the
# paper's Table 1. Usage: bash scripts/install_check.sh (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$prefix" "$work"' EXIT
cmake --install build --prefix "$prefix" > /dev/null
# The snippet is the ```cpp block after "<!-- library snippet -->" in README.md.
awk '/<!-- library snippet -->/{on=1; next} on && /^```cpp/{code=1; next}
     code && /^```/{exit} code' README.md > "$work/snippet.cc"
[ -s "$work/snippet.cc" ] || { echo "install_check: README.md: no library snippet" >&2; exit 1; }
mkdir -p "$work/snippet"
cp "$work/snippet.cc" "$work/snippet/main.cc"
cat > "$work/snippet/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(snippet LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(ringid REQUIRED)
add_executable(snippet main.cc)
target_link_libraries(snippet PRIVATE ringid::ringid)
CMAKE
for project in examples "$work/snippet"; do
  name=$(basename "$project")
  cmake -S "$project" -B "$work/build-$name" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
  cmake --build "$work/build-$name" -j"$(nproc)" > /dev/null
done
"$work/build-examples/identify_parameters" datasets/paper/table1.json "$work/report.json"
# The report written through the installed headers reads back in the tool.
"$prefix/bin/ringid" report --input="$work/report.json" --output="$work/report.html" > /dev/null
"$work/build-snippet/snippet" datasets/paper/table1.json
# The installed executable runs too, from any directory, on the data installed
# with it (PREFIX/share/ringid).
"$prefix/bin/ringid" help > /dev/null
(cd "$work" && "$prefix/bin/ringid" bench --suite=paper > /dev/null)
# The Python module, where Debian's python3 looks under the prefix, when it was built.
module=$(find "$prefix" -name 'ringid.cpython-*.so' -path '*dist-packages*' | head -1)
if [ -n "$module" ]; then
  PYTHONPATH=$(dirname "$module") /usr/bin/python3 -c \
    "import ringid; ringid.identify('datasets/paper/table1.json', starts=1)"
  # The module's sources build against the installed headers alone:
  # python/ copied away from the tree, so that no header of the tree is found.
  mkdir -p "$work/module/src"
  cp -r python "$work/module/src/"
  cat > "$work/module/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(module LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 17)
set(Python_EXECUTABLE /usr/bin/python3)
set(PYBIND11_FINDPYTHON ON)
set(CMAKE_INTERPROCEDURAL_OPTIMIZATION OFF)  # as python/CMakeLists.txt: no minutes of LTO
find_package(Python COMPONENTS Interpreter Development.Module REQUIRED)
find_package(pybind11 CONFIG REQUIRED)
find_package(ringid REQUIRED)
find_package(glog REQUIRED)
file(GLOB sources src/python/*.cc)
pybind11_add_module(ringid_module ${sources})
set_target_properties(ringid_module PROPERTIES OUTPUT_NAME ringid)
target_include_directories(ringid_module PRIVATE src)
target_link_libraries(ringid_module PRIVATE ringid::ringid glog::glog)
target_compile_definitions(ringid_module PRIVATE RINGID_VERSION="installed")
CMAKE
  cmake -S "$work/module" -B "$work/build-module" -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
  cmake --build "$work/build-module" -j"$(nproc)" > /dev/null
  PYTHONPATH="$work/build-module" /usr/bin/python3 -c "
import ringid
assert ringid.__version__ == 'installed', ringid.__file__
p = ringid.Problem('datasets/paper/table1.json')
assert p.jacobian(p.start).shape == (p.num_residuals, len(p.start))
ringid.identify('datasets/paper/table1.json', starts=1)"
fi
echo "install check: examples, README snippet and Python module built against $prefix and ran"
