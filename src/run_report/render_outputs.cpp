#include "run_report/render_outputs.hpp"

#include "base/counted.hpp"
#include "run_report/comparison_report.hpp"
#include "run_report/verify_report.hpp"

#include <nlohmann/json.hpp>

#include <sstream>

namespace twinraster::run_report {

namespace {

using Json = nlohmann::ordered_json;

Json OrNull(const std::string& text) { return text.empty() ? Json(nullptr) : Json(text); }

Json BackendJson(const run::BackendRecord* b) {
  if (!b) return nullptr;  // the backend was not asked for
  return {{"status", run::StatusName(b->status)},
          {"problem", OrNull(b->problem)},
          {"output", OrNull(b->output)},
          {"device", b->detail},
          {"driver", OrNull(b->driver)},
          {"timings_ms",
           {{"setup", b->setup_ms},
            {"draw", b->draw_ms},
            {"readback", b->readback_ms},
            {"png", b->png_ms},
            {"isolation", b->isolation_ms}}}};
}

Json TwinJson(const std::optional<twin_rules::TwinRules>& twin) {
  if (!twin) return nullptr;
  const auto release_field = [&](const std::string twin_rules::LavapipeRelease::*field) {
    return twin->release ? Json((*twin->release).*field) : Json(nullptr);
  };
  return {{"exact", twin->exact},
          {"rasterizer", twin->rules.rasterizer == cpu::Rasterizer::kSwiftShader ? "swiftshader" : "lavapipe"},
          {"text", twin->text},
          {"mesa", release_field(&twin_rules::LavapipeRelease::mesa)},
          {"llvm", release_field(&twin_rules::LavapipeRelease::llvm)},
          {"cpu_path", twin->path.Text()},
          {"instruction_set", twin->path.InstructionSet()},
          {"vector_bits", twin->release ? twin->release->vector_bits : twin->path.vector_bits}};
}

std::string BackendText(const run::BackendRecord& b) {
  const std::string name = b.Name();
  if (!b.Drawn()) return name + ": " + b.problem + "; no " + name + " image";
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << name << ": " << (b.output == "-" ? "standard output" : b.output) << "  (" << b.detail
    << ")  setup " << b.setup_ms << " ms, draw " << b.draw_ms << " ms, readback " << b.readback_ms << " ms, png "
    << b.png_ms << " ms";
  if (b.backend == run::Backend::kGpu) s << ", process " << b.isolation_ms << " ms";
  return s.str();
}

}  // namespace

std::string RenderText(const run::RunRecord& r, bool verify_asked) {
  std::ostringstream out;
  std::ostringstream head;
  head.precision(3);
  head << std::fixed << r.scene << ": " << Counted(r.instances, "instance") << ", " << Counted(r.triangles, "triangle")
       << ", " << r.width << " x " << r.height << ", loaded in " << r.load_ms << " ms";
  out << head.str() << "\n";
  for (const run::BackendRecord& b : r.backends) out << BackendText(b) << "\n";
  if (r.twin) out << "twin: " << r.twin->text << "\n";
  if (r.comparison) {
    out << "gpu vs cpu: " << ComparisonText(r.width, r.height, *r.comparison)
        << (r.diff.empty() ? "" : ", diff in " + r.diff)
        << (!r.comparison->Equal() && r.twin && !r.twin->exact
                ? " (the twin has no rules for this driver: not a verdict)"
                : "")
        << "\n";
  } else if (r.backends.size() == 2) {
    out << "gpu vs cpu: not compared, there is no gpu image\n";
  }
  if (r.verification && r.comparison && !r.comparison->Equal()) {
    out << "verdict: " << DifferenceText(r.comparison->differing_pixels, *r.verification) << "\n";
  }
  if (r.verification && verify_asked) {
    out << "verify: " << run::BackendName(*r.judged) << " image " << VerificationText(*r.verification)
        << (r.map.empty() ? "" : ", map in " + r.map) << "\n";
  }
  return out.str();
}

Json RenderJson(const run::RunRecord& r) {
  // A scene that failed (verdict "error") has its line too, with what the scene would have told
  // (its size, its counts, what drew) null: a batch's JSON has one line per scene, as its page.
  const bool read = r.verdict != run::Verdict::kError;
  const auto if_read = [read](const Json& value) { return read ? value : Json(nullptr); };
  Json j;
  j["format"] = kRenderJsonFormat;
  j["scene"] = r.scene;
  j["verdict"] = run::VerdictName(r.verdict);
  j["exit_code"] = run::ExitCodeOf(r.verdict);
  j["reason"] = VerdictReason(r);
  j["rules"] = run::RulesName(r.rules);
  j["wireframe"] = if_read(r.wireframe);
  j["width"] = if_read(r.width);
  j["height"] = if_read(r.height);
  j["instances"] = if_read(r.instances);
  j["triangles"] = if_read(r.triangles);
  j["load_ms"] = if_read(r.load_ms);
  j["differing_pixels"] = r.comparison ? Json(r.comparison->differing_pixels) : Json(nullptr);
  j["max_channel_difference"] = r.comparison ? Json(r.comparison->max_channel_difference) : Json(nullptr);
  j["diff"] = OrNull(r.diff);
  j["backends"] = {{"gpu", BackendJson(r.Find(run::Backend::kGpu))}, {"cpu", BackendJson(r.Find(run::Backend::kCpu))}};
  j["twin_rules"] = TwinJson(r.twin);
  if (r.verification) {
    Json v;
    v["image"] = run::BackendName(*r.judged);
    const Json judged =
        VerificationJson(*r.verification, r.map.empty() ? std::nullopt : std::optional(r.map), r.verify_ms);
    for (const auto& [key, value] : judged.items()) v[key] = value;
    j["verify"] = v;
  } else {
    j["verify"] = nullptr;
  }
  return j;
}

std::string VerdictReason(const run::RunRecord& r) {
  switch (r.verdict) {
    case run::Verdict::kError: return r.error;
    case run::Verdict::kCrashed:
      for (const run::BackendRecord& b : r.backends) {
        if (!b.Drawn()) return std::string(b.Name()) + " " + run::StatusName(b.status) + ": " + b.problem;
      }
      return "crashed";
    case run::Verdict::kDiffering:
    case run::Verdict::kInconclusive:
    case run::Verdict::kVerified:
      if (r.Differ() && r.verification) return DifferenceText(r.comparison->differing_pixels, *r.verification);
      if (r.verification) {
        return std::string(run::BackendName(*r.judged)) + " image " + VerificationText(*r.verification);
      }
      return "the images differ in " + std::to_string(r.comparison->differing_pixels) + " px";
    case run::Verdict::kIdentical: return "0 differing pixels";
    case run::Verdict::kRendered: return "drawn";
  }
  return "";
}

}  // namespace twinraster::run_report
