# Sourced by the build scripts: `source compiler-cache.sh SOURCE_DIR` sets `compiler_cache` to the
# CMake arguments that compile through ccache (empty when ccache is not installed) and exports
# CCACHE_BASEDIR=SOURCE_DIR, so that paths under the sources reach ccache relative to the build
# directory and a copy of the sources built in its own build/ (Testing/Utilities/TestNewFilter.sh)
# finds the objects of SOURCE_DIR/build.
compiler_cache=()
if command -v ccache >/dev/null; then
  compiler_cache=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=$1
fi
