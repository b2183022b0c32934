# Sourced by build.sh, test.sh and fuzz.sh: the compiler cache (Debian's ccache, which
# scripts/setup.sh installs). The same sources compiled again, in this folder or in
# another clone of the repository (CI's), are taken from the cache instead of being
# compiled: paths below the repository are hashed relative to it (CCACHE_BASEDIR,
# CCACHE_NOHASHDIR), and the precompiled headers are cacheable (CCACHE_SLOPPINESS, as
# ccache's manual asks for them). A build with an empty cache, or without ccache, is
# the same build. FERAN_CCACHE=0 turns it off.
# Sets feran_launcher: the CMake arguments that compile through the cache.
feran_launcher=()
if [ "${FERAN_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
  CCACHE_BASEDIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  export CCACHE_BASEDIR
  export CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
  export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-8G}"
  feran_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
else
  feran_launcher=(-UCMAKE_CXX_COMPILER_LAUNCHER)
fi
