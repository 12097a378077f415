// The rules the twin follows for one device: for lavapipe, the release read from the device
// (driverInfo and the "LLVM x, N bits" in its name) and the CPU path read from this machine
// (lavapipe_path.hpp); for SwiftShader, its driver version, JIT and subpixel bits. Then the twin's
// table of what it copies bit for bit. Any other driver, release or path is named as such ("no
// bit-exact rules for ..."), never compared as if it were known. It does not read the device: the
// caller hands in what the device said.
#pragma once

#include "cpu/raster_rules.hpp"
#include "twin_rules/lavapipe_path.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace twinraster::twin_rules {

// What a lavapipe device says of itself.
struct LavapipeRelease {
  std::string mesa;  // "22.3.6", from driverInfo "Mesa 22.3.6 (LLVM 15.0.6)"
  std::string llvm;  // "15.0.6", from the device name "llvmpipe (LLVM 15.0.6, 256 bits)"
  int vector_bits = 0;
};

// Empty when the device is not lavapipe (or says too little to tell its release).
std::optional<LavapipeRelease> ParseLavapipe(const std::string& device_name, const std::string& driver_info);

// What a device says of itself (vkGetPhysicalDeviceProperties2 with its driver properties); all
// empty or 0 when no device was asked.
struct DeviceFacts {
  std::string name;         // deviceName
  std::string driver_info;  // driverInfo
  std::uint32_t driver_id = 0, driver_version = 0, subpixel_bits = 0;
};

struct TwinRules {
  bool exact = false;      // the twin has bit-exact rules for this driver and path
  cpu::RasterRules rules;  // what the twin follows: the matched rules, or the defaults when not exact
  std::string device;      // the device's name, the name asked when none was opened, or empty
  std::optional<LavapipeRelease> release;
  CpuPath path;
  // "lavapipe rules, Mesa 25.0.7, x86-64 SSE4.1, 128-bit", or
  // "no bit-exact rules for Mesa 25.1.2 (LLVM 19.1.7): ...".
  std::string text;
};

// A device with no name: none was asked; the twin follows lavapipe's default release on this
// machine's path and says so.
TwinRules ChooseTwinRules(const DeviceFacts& device, const CpuPath& path);

// The rules for a device asked by name (--device) when none is opened to say what it is: the
// family the name asks for (base/device_names.hpp; lavapipe first when it asks for both), with
// lavapipe's default release or SwiftShader's row, on this machine's path, said to be chosen by
// the name. Throws UsageError when the twin has no bit-exact rules for what the name asks for.
TwinRules ChooseTwinRulesByName(const std::string& asked, const CpuPath& path);

// One lavapipe the twin copies bit for bit: a release named exactly (another point release may
// have changed the arithmetic, and only a run can say it has not), one CPU path, its rules, and
// the CI step that renders on that very driver and path and finds 0 differing pixels.
struct KnownLavapipe {
  std::string_view mesa;
  std::string_view llvm_major;       // LLVM's major version the release was proven with
  std::string_view instruction_set;  // CpuPath::InstructionSet()
  int vector_bits;
  cpu::RasterRules rules;
  std::string_view proven_by;  // empty: proven by hand once, by no CI step (--version says so)
};

// The table, in the order --version lists it.
std::span<const KnownLavapipe> KnownLavapipes();

// A path of a release in the table that has no row, and why: render's "no bit-exact rules" text
// and --version give the reason, and the tests skip it rather than fail as for a forgotten row.
struct UnprovenLavapipe {
  std::string_view mesa;
  std::string_view llvm_major;
  std::string_view instruction_set;
  int vector_bits;
  std::string_view why;
};
std::span<const UnprovenLavapipe> UnprovenLavapipes();

// The one SwiftShader the twin copies: the device reports no revision (its driverVersion has been
// 5.0.0 for years), so the row is keyed on what it does report and names the package it was
// proven on; its CI step renders every shipped scene on the installed SwiftShader, so a package
// that changed the rasterizer fails there.
struct KnownSwiftShader {
  std::string_view name;  // deviceName: the JIT is in it, and "(LLVM)" rounds differently
  std::uint32_t driver_version;
  std::uint32_t subpixel_bits;  // 4 in Chromium's build (SWIFTSHADER_LEGACY_PRECISION), 8 upstream
  std::string_view proven_on;   // the packages whose libvk_swiftshader.so the CI steps ran it against
  cpu::RasterRules rules;
  std::string_view proven_by;
};
const KnownSwiftShader& SwiftShaderRow();

// The releases and paths the table knows, one line each, with what proves each, then the
// unproven ones with why, for --version.
std::string KnownRulesText();

}  // namespace twinraster::twin_rules
