// osgdb_serializers_osgwater: osgDB's second try for a file that names an osgWater class, after the
// node kit itself (libosgWater.so, the development link, which a runtime-only install lacks). It
// holds nothing of its own: loading it loads the kit, whose wrappers register as the kit loads.
#include <osgWater/Version>

namespace {
// A use of the kit, so that no linker drops it from this plugin's dependencies (--as-needed).
[[maybe_unused]] const char* const kitVersion = osgWater::getVersion();
} // namespace
