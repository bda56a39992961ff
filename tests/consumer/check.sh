#!/usr/bin/env bash
# Installs the build into a private prefix and builds + runs a consumer with find_package(osgWater);
# the consumer also builds the README's code blocks marked "<!-- compiled", as written.
set -euo pipefail
bin="$1"; src="$2"
# $3: compiler flags the library was built with that a consumer must share (the sanitizer build's:
# an uninstrumented program cannot load an ASan library)
flags="${3:-}"
readme="$4"
# $6 (optional): a second page whose marked blocks are built too (docs/USING.md)
# $5: the declared public headers (comma-separated names): exactly these are installed
public="${5:-}"
rm -rf "$bin/_install" "$bin/_consumer" "$bin/_readme"
mkdir -p "$bin/_readme"
# each marked block to its own file: readme_1.cpp, readme_2.cpp, ...
awk -v dir="$bin/_readme" '
  /^<!-- compiled/ { marked = 1; next }
  marked && /^```cpp/ { n++; file = dir "/readme_" n ".cpp"; inside = 1; marked = 0; next }
  inside && /^```/ { inside = 0; close(file); next }
  inside { print > file; next }
  { marked = 0 }' "$readme" "${6:-/dev/null}"
ls "$bin"/_readme/readme_*.cpp > /dev/null  # at least one block, or the README lost its examples
cmake --install "$bin" --prefix "$bin/_install" > /dev/null
# the installed headers are the declared public set, no more and no fewer
installed=$(ls "$bin/_install/include/osgWater" | sort | tr '\n' ' ')
declared=$(echo "$public" | tr ',' '\n' | sort | tr '\n' ' ')
if [ "$installed" != "$declared" ]; then
  echo "installed headers: $installed"; echo "declared public:   $declared"; exit 1
fi
# each compiles alone with only the prefix and OSG on the include path, and none reaches glm: a
# glm/glm.hpp that stops the compiler stands first on the path
mkdir -p "$bin/_poison/glm"
for f in glm.hpp gtc/type_ptr.hpp gtc/matrix_transform.hpp; do
  mkdir -p "$(dirname "$bin/_poison/glm/$f")"; echo '#error "a public osgWater header includes glm"' > "$bin/_poison/glm/$f"
done
for h in $(ls "$bin/_install/include/osgWater"); do
  echo "#include <osgWater/$h>" | ${CXX:-c++} -std=c++17 -fsyntax-only -x c++ -I"$bin/_poison" -I"$bin/_install/include" - \
    || { echo "the public header osgWater/$h does not compile alone"; exit 1; }
done
cmake -S "$src" -B "$bin/_consumer" -DCMAKE_PREFIX_PATH="$bin/_install" -DREADME_BLOCKS="$bin/_readme" \
  ${flags:+"-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags"} > /dev/null
cmake --build "$bin/_consumer" > /dev/null
LD_LIBRARY_PATH="$bin/_install/lib:$bin/_install/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}" "$bin/_consumer/consumer"
