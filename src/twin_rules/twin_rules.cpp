#include "twin_rules/twin_rules.hpp"

#include "base/device_names.hpp"
#include "base/usage_error.hpp"

#include <array>
#include <regex>
#include <span>
#include <string_view>

namespace twinraster::twin_rules {
namespace {

// The default release: the one the twin was first written against (Debian 12's).
constexpr std::string_view kDefaultMesa = "22.3.6";

// Mesa 22.3.6: the JIT fuses where the CPU path has FMA; lines round half away, and are clipped at
// the view volume like triangles.
constexpr cpu::RasterRules kMesa22Fma{.fused_multiply_add = true};
constexpr cpu::RasterRules kMesa22NoFma{.fused_multiply_add = false};
// Mesa 22.3.6 built without SSE (aarch64): triangles snap half away from zero; NEON fuses.
constexpr cpu::RasterRules kMesa22Aarch64{.fused_multiply_add = true, .triangles_round_half_away = true};
// Mesa 25.0: lines round half to even (util_iround became lrintf) and polygon mode LINE clips x and
// y at the guard band.
constexpr cpu::RasterRules kMesa25Fma{
    .fused_multiply_add = true, .lines_round_half_even = true, .wireframe_guard_band = true};
constexpr cpu::RasterRules kMesa25NoFma{
    .fused_multiply_add = false, .lines_round_half_even = true, .wireframe_guard_band = true};

// The sse4.1 path (GALLIUM_OVERRIDE_CPU_CAPS=sse4.1, or an x86-64 CPU without AVX) has no FMA and
// 128-bit vectors; LP_NATIVE_VECTOR_WIDTH=128 keeps FMA. Debian 12 builds Mesa 22.3.6 with LLVM 15;
// Mesa 25.0.7 is Debian 13's (LLVM 19) and Debian 12's backport (LLVM 15).
// Each row names the CI step (.ci/run) that proves it; docs/lavapipe-paths.md gives the counts.
constexpr std::string_view kDebian12Suite = "the whole suite on Debian 12 (scripts/test.sh, check-debian.sh bookworm)";
constexpr std::string_view kDebian12Sse41 = "the suite's \"sse4.1 path:\" entries on Debian 12";
constexpr std::string_view kDebian12Wide128 = "the 128-bit render test (lavapipe_paths_cli_test) on Debian 12";
constexpr std::string_view kAarch64 = ".ci/check-aarch64.sh, a sample under qemu with Debian 12's arm64 lavapipe";
constexpr std::string_view kBackport = ".ci/check-mesa25-bookworm.sh: every shipped scene on Debian 12's backport";
constexpr std::string_view kDebian13Suite = "the whole suite in a Debian 13 root (check-debian.sh trixie)";
constexpr std::string_view kDebian13Sse41 = "the suite's \"sse4.1 path:\" entries in a Debian 13 root";
constexpr std::array kKnown = {
    KnownLavapipe{"22.3.6", "15", "AVX2+FMA", 256, kMesa22Fma, kDebian12Suite},
    KnownLavapipe{"22.3.6", "15", "AVX2+FMA", 128, kMesa22Fma, kDebian12Wide128},
    KnownLavapipe{"22.3.6", "15", "SSE4.1", 128, kMesa22NoFma, kDebian12Sse41},
    KnownLavapipe{"22.3.6", "15", "NEON", 128, kMesa22Aarch64, kAarch64},
    KnownLavapipe{"25.0.7", "15", "AVX2+FMA", 256, kMesa25Fma, kBackport},
    KnownLavapipe{"25.0.7", "15", "AVX2+FMA", 128, kMesa25Fma, kBackport},
    KnownLavapipe{"25.0.7", "15", "SSE4.1", 128, kMesa25NoFma, kBackport},
    KnownLavapipe{"25.0.7", "19", "AVX2+FMA", 256, kMesa25Fma, kDebian13Suite},
    KnownLavapipe{"25.0.7", "19", "SSE4.1", 128, kMesa25NoFma, kDebian13Sse41},
};

constexpr std::uint32_t kSwiftShaderDriverId = 10;     // VK_DRIVER_ID_GOOGLE_SWIFTSHADER
constexpr std::uint32_t kSwiftShader500 = (5u << 22);  // VK_MAKE_VERSION(5, 0, 0)
// Subzero never fuses and never approximates a reciprocal; the threads run with denormals as zero.
constexpr KnownSwiftShader kSwiftShader{
    .name = "SwiftShader Device (Subzero)",
    .driver_version = kSwiftShader500,
    .subpixel_bits = 4,
    .proven_on = "Debian's chromium-common 150.0.7871.100 and 156.0.8078.108 (Debian 12) and 156.0.8078.79 (Debian 13)",
    .rules = {.rasterizer = cpu::Rasterizer::kSwiftShader, .flush_denormals = true, .fused_multiply_add = false},
    .proven_by =
        "the SwiftShader twin tests (tests/twin/swiftshader_twin_test.cpp) wherever the suite runs: "
        "scripts/test.sh, check-debian.sh bookworm and trixie"};

constexpr std::array kUnproven = {
    UnprovenLavapipe{"25.0.7", "19", "AVX2+FMA", 128,
                     "lavapipe corrupts its heap and crashes on up to a third of the shipped scenes "
                     "(docs/mesa-128bit-crash.md), so no run has proven the rest"},
};

// "15.0.6" -> "15"; "15" stays.
std::string Major(const std::string& version) { return version.substr(0, version.find('.')); }

// The row of `table` (known or unproven) for this release and path, or null.
template <typename Row, std::size_t N>
const Row* Find(const std::array<Row, N>& table, const LavapipeRelease& release, const CpuPath& path) {
  for (const Row& row : table) {
    if (row.mesa == release.mesa && row.llvm_major == Major(release.llvm) &&
        row.instruction_set == path.InstructionSet() && row.vector_bits == release.vector_bits) {
      return &row;
    }
  }
  return nullptr;
}

std::string PathText(const CpuPath& path, int vector_bits) {
  CpuPath shown = path;
  shown.vector_bits = vector_bits;
  return shown.Text();
}

}  // namespace

std::optional<LavapipeRelease> ParseLavapipe(const std::string& device_name, const std::string& driver_info) {
  static const std::regex name_pattern(R"(^llvmpipe \(LLVM ([0-9.]+), ([0-9]+) bits\)$)");
  static const std::regex info_pattern(R"(^Mesa ([0-9]+\.[0-9]+\.[0-9]+)(-devel)?\b)");
  std::smatch name, info;
  if (!std::regex_search(device_name, name, name_pattern)) return std::nullopt;
  if (!std::regex_search(driver_info, info, info_pattern)) return std::nullopt;
  LavapipeRelease release;
  release.mesa = info[1].str() + info[2].str();
  release.llvm = name[1].str();
  release.vector_bits = std::stoi(name[2].str());
  return release;
}

namespace {

std::string VersionText(std::uint32_t v) {
  return std::to_string(v >> 22) + "." + std::to_string((v >> 12) & 0x3ff) + "." + std::to_string(v & 0xfff);
}

bool IsSwiftShader(const DeviceFacts& device) {
  return device.driver_id == kSwiftShaderDriverId || device.name.starts_with("SwiftShader");
}

// SwiftShader's row when the device and this CPU are the ones it was proven on; else why not.
// `chosen_by`, when set, says how the row was chosen without a device.
TwinRules ChooseSwiftShader(const DeviceFacts& device, const CpuPath& path, const std::string& chosen_by = "") {
  TwinRules twin;
  twin.device = device.name;
  twin.path = path;
  const KnownSwiftShader& row = kSwiftShader;
  const std::string seen = device.name + ", driver " + VersionText(device.driver_version) + ", " +
                           std::to_string(device.subpixel_bits) + " subpixel bits";
  const std::string known = "the twin copies " + std::string(row.name) + ", driver " + VersionText(row.driver_version) +
                            ", " + std::to_string(row.subpixel_bits) + " subpixel bits, on x86-64 with SSE4.1";
  if (device.driver_id != kSwiftShaderDriverId || device.name != row.name ||
      device.driver_version != row.driver_version || device.subpixel_bits != row.subpixel_bits ||
      path.arch != "x86-64" || !path.cpuid_sse4_1) {
    twin.text = "no bit-exact rules for " + seen + " on " + path.arch + (path.cpuid_sse4_1 ? "" : " without SSE4.1") +
                ": " + known;
    return twin;
  }
  twin.exact = true;
  twin.rules = row.rules;
  twin.text = "SwiftShader rules" + (chosen_by.empty() ? "" : " (" + chosen_by + ")") + ", " + seen +
              ", x86-64 SSE4.1, proven on " + std::string(row.proven_on);
  return twin;
}

// No device opened: lavapipe's default release, on the path lavapipe would take here; `why` says
// what the release was assumed from.
TwinRules AssumedLavapipe(const CpuPath& path, const std::string& why) {
  TwinRules twin;
  twin.path = path;
  LavapipeRelease assumed{std::string(kDefaultMesa), "", path.vector_bits};
  for (const KnownLavapipe& known : kKnown) {
    if (known.mesa == kDefaultMesa) assumed.llvm = known.llvm_major;
  }
  if (const KnownLavapipe* known = Find(kKnown, assumed, path)) {
    twin.exact = true;
    twin.rules = known->rules;
    twin.release = assumed;
    twin.text = "lavapipe rules, Mesa " + assumed.mesa + " (assumed: " + why + "), " + path.Text();
    return twin;
  }
  twin.text = "no bit-exact rules for Mesa " + assumed.mesa + " on " + path.Text();
  return twin;
}

// The name is none the twin can tell rules from: which are, and what a backend's name means.
std::string NoRulesForName(const std::string& asked) {
  std::string text = "--device '" + asked +
                     "': with no device opened (--backend cpu) the twin takes its rules from the name alone, "
                     "and knows lavapipe (or part of 'llvmpipe') and swiftshader (or part of '" +
                     std::string(kSwiftShader.name) + "')";
  if (const std::string hint = BackendNotDevice(asked); !hint.empty()) return text + "; " + hint;
  return text + "; to draw on the device itself, and compare, use --backend both";
}

// Whether `asked` names `family` with no device opened: its common name, or a part of `reference`,
// the name of the device the twin copies (for lavapipe "llvmpipe" alone: the rest of its names
// tells a release, which only the device could confirm).
bool NamesWithoutDevice(const std::string& asked, const DeviceFamily& family, std::string_view reference) {
  return !asked.empty() && (EqualsIgnoringCase(asked, family.common_name) || ContainsIgnoringCase(reference, asked));
}

}  // namespace

TwinRules ChooseTwinRulesByName(const std::string& asked, const CpuPath& path) {
  const std::string chosen_by = "'" + asked + "' asked, no device opened";
  TwinRules twin;
  if (NamesWithoutDevice(asked, kLavapipeFamily, kLavapipeFamily.name_start)) {
    twin = AssumedLavapipe(path, chosen_by);
  } else if (NamesWithoutDevice(asked, kSwiftShaderFamily, kSwiftShader.name)) {
    const DeviceFacts row{.name = std::string(kSwiftShader.name),
                          .driver_info = "",
                          .driver_id = kSwiftShaderDriverId,
                          .driver_version = kSwiftShader.driver_version,
                          .subpixel_bits = kSwiftShader.subpixel_bits};
    twin = ChooseSwiftShader(row, path, chosen_by);
  } else {
    throw UsageError(NoRulesForName(asked));
  }
  if (!twin.exact) throw UsageError("--device '" + asked + "': " + twin.text);
  twin.device = asked;
  return twin;
}

TwinRules ChooseTwinRules(const DeviceFacts& facts, const CpuPath& path) {
  const std::string& device_name = facts.name;
  const std::string& driver_info = facts.driver_info;
  if (IsSwiftShader(facts)) return ChooseSwiftShader(facts, path);
  if (device_name.empty()) return AssumedLavapipe(path, "no device was asked");
  TwinRules twin;
  twin.device = device_name;
  twin.path = path;
  twin.release = ParseLavapipe(device_name, driver_info);
  if (!twin.release) {
    twin.text = "no bit-exact rules for " + device_name + (driver_info.empty() ? "" : " (" + driver_info + ")") +
                ": the twin copies lavapipe and SwiftShader only";
    return twin;
  }
  const LavapipeRelease& release = *twin.release;
  const std::string where = PathText(path, release.vector_bits);
  if (const KnownLavapipe* known = Find(kKnown, release, path)) {
    twin.exact = true;
    twin.rules = known->rules;
    twin.text = "lavapipe rules, Mesa " + release.mesa + ", " + where;
    return twin;
  }
  twin.text = "no bit-exact rules for Mesa " + release.mesa + " (LLVM " + release.llvm + ") on " + where;
  if (const UnprovenLavapipe* unproven = Find(kUnproven, release, path)) twin.text += ": " + std::string(unproven->why);
  return twin;
}

const KnownSwiftShader& SwiftShaderRow() { return kSwiftShader; }

std::span<const KnownLavapipe> KnownLavapipes() { return kKnown; }
std::span<const UnprovenLavapipe> UnprovenLavapipes() { return kUnproven; }

std::string KnownRulesText() {
  std::string text;
  for (const KnownLavapipe& known : kKnown) {
    text += "  Mesa " + std::string(known.mesa) + " (LLVM " + std::string(known.llvm_major) + "), " +
            std::string(known.instruction_set) + ", " + std::to_string(known.vector_bits) + "-bit: " +
            (known.proven_by.empty() ? "not proven by any CI step (by hand once, docs/lavapipe-paths.md)"
                                     : "proven in CI by " + std::string(known.proven_by)) +
            "\n";
  }
  text += "  " + std::string(kSwiftShader.name) + ", driver " + VersionText(kSwiftShader.driver_version) + ", " +
          std::to_string(kSwiftShader.subpixel_bits) + " subpixel bits, x86-64 SSE4.1 (proven on " +
          std::string(kSwiftShader.proven_on) + "): proven in CI by " + std::string(kSwiftShader.proven_by) + "\n";
  for (const UnprovenLavapipe& unproven : kUnproven) {
    text += "  (no rules for Mesa " + std::string(unproven.mesa) + " (LLVM " + std::string(unproven.llvm_major) +
            "), " + std::string(unproven.instruction_set) + ", " + std::to_string(unproven.vector_bits) +
            "-bit: " + std::string(unproven.why) + ")\n";
  }
  return text;
}

}  // namespace twinraster::twin_rules
