#include "parameter_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "scene/overrides.h"
#include "scene/scene_io.h"

namespace lagoon::demo {
namespace {

using ordered_json = nlohmann::ordered_json;

ordered_json::json_pointer pointer(const std::string& path) {
  std::string p = "/" + path;
  std::replace(p.begin(), p.end(), '.', '/');
  return ordered_json::json_pointer(p);
}

// Finite widget limits from the field's bounds; an open bound steps just inside.
void limits(const scene::Bounds& b, double& lo, double& hi) {
  lo = std::isfinite(b.min) ? b.min : -1e9;
  hi = std::isfinite(b.max) ? b.max : 1e9;
  if (b.min_open) lo = std::nextafter(float(lo), std::numeric_limits<float>::infinity());
  if (b.max_open) hi = std::nextafter(float(hi), -std::numeric_limits<float>::infinity());
}

// ImGui's built-in font is ASCII only: spell out the symbols the field docs use instead of showing '?'.
std::string ascii(std::string text) {
  static const std::pair<const char*, const char*> symbols[] = {
      {"²", "^2"},     {"³", "^3"},    {"·", "*"},     {"−", "-"},     {"×", "x"},
      {"–", "-"},      {"…", "..."},   {"≤", "<="},    {"≥", ">="},    {"→", "->"},
      {"°", " deg"},   {"γ", "gamma"}, {"θ", "theta"}, {"ω", "omega"}, {"π", "pi"},
      {"λ", "lambda"}, {"σ", "sigma"}, {"Ψ", "Psi"},   {"\u0302", ""}};  // U+0302: the hat of R-hat
  for (const auto& [from, to] : symbols)
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + std::strlen(to)))
      text.replace(at, std::strlen(from), to);
  return text;
}

void tooltip(const scene::FieldInfo& f) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
  ImGui::TextUnformatted(f.path.c_str());
  ImGui::TextUnformatted(ascii(f.doc).c_str());
  ImGui::TextDisabled("%s%s%s", ascii(f.range).c_str(), f.unit.empty() ? "" : ", in ", f.unit.c_str());
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

// A combo of the field's fixed values (integers stay numbers).
bool edit_choice(const scene::FieldInfo& f, const std::string& label, ordered_json& v) {
  bool changed = false;
  const std::string current = v.is_string() ? v.get<std::string>() : safe_dump(v);
  if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
    for (const std::string& choice : f.choices) {
      if (ImGui::Selectable(choice.c_str(), choice == current)) {
        v = f.type == "integer" ? ordered_json(std::stoll(choice)) : ordered_json(choice);
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool edit_text(const std::string& label, ordered_json& v) {
  std::string text = v.get<std::string>();
  // Applied on Enter or when leaving the field: a half-typed file name is not worth a reload.
  if (ImGui::InputText(label.c_str(), &text, ImGuiInputTextFlags_EnterReturnsTrue) ||
      ImGui::IsItemDeactivatedAfterEdit()) {
    const bool changed = v.get<std::string>() != text;
    v = text;
    return changed;
  }
  return false;
}

// Two or three numbers: drags within [lo, hi], or a colour picker for "[r, g, b]".
bool edit_vector(const scene::FieldInfo& f, const std::string& label, ordered_json& v, double lo, double hi) {
  bool changed = false;
  float x[3] = {0, 0, 0};
  for (size_t i = 0; i < v.size(); ++i) x[i] = v[i].get<float>();
  if (f.type == "[r, g, b]") {
    // HDR: light colours may exceed 1 (the field's bounds clamp them below).
    changed = ImGui::ColorEdit3(label.c_str(), x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    for (float& c : x) c = std::clamp(c, float(lo), float(hi));
  } else {
    const float flo = float(lo), fhi = float(hi);
    changed = v.size() == 2
                  ? ImGui::DragFloat2(label.c_str(), x, 0.1f, flo, fhi, "%.3g", ImGuiSliderFlags_AlwaysClamp)
                  : ImGui::DragFloat3(label.c_str(), x, 0.1f, flo, fhi, "%.3g", ImGuiSliderFlags_AlwaysClamp);
  }
  if (changed)
    for (size_t i = 0; i < v.size(); ++i) v[i] = x[i];
  return changed;
}

// One widget for value `v` of field `f`; true when the user changed it.
bool edit_value(const scene::FieldInfo& f, const std::string& label, ordered_json& v) {
  double lo = 0, hi = 0;
  limits(f.bounds, lo, hi);
  bool changed = false;
  if (!f.choices.empty()) {
    changed = edit_choice(f, label, v);
  } else if (f.type == "number" && v.is_number()) {
    double x = v.get<double>();
    const float speed = float(std::max(std::abs(x) * 0.01, 0.001));
    changed = ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &x, speed, &lo, &hi, "%.4g",
                                ImGuiSliderFlags_AlwaysClamp);
    if (changed) v = x;
  } else if (f.type == "integer" && v.is_number()) {
    uint32_t x = v.get<uint32_t>();
    const uint32_t ulo = uint32_t(std::max(lo, 0.0)), uhi = uint32_t(std::min(hi, 4294967295.0));
    changed = ImGui::DragScalar(label.c_str(), ImGuiDataType_U32, &x, 1.0f, &ulo, &uhi, "%u",
                                ImGuiSliderFlags_AlwaysClamp);
    if (changed) v = x;
  } else if (f.type == "boolean" && v.is_boolean()) {
    bool x = v.get<bool>();
    changed = ImGui::Checkbox(label.c_str(), &x);
    if (changed) v = x;
  } else if (f.type == "string" && v.is_string()) {
    changed = edit_text(label, v);
  } else if (f.type.front() == '[' && v.is_array() && (v.size() == 2 || v.size() == 3)) {
    changed = edit_vector(f, label, v, lo, hi);
  } else {
    ImGui::TextDisabled("%s: %s", label.c_str(), safe_dump(v).c_str());
  }
  tooltip(f);
  return changed;
}

// The element rows ("ocean.cascades[].patch_size_m") that follow array row `a` in the field table.
std::vector<const scene::FieldInfo*> element_fields(const std::vector<scene::FieldInfo>& fields, size_t a) {
  std::vector<const scene::FieldInfo*> out;
  const std::string prefix = fields[a].path + "[].";
  for (size_t i = a + 1; i < fields.size() && fields[i].path.rfind(prefix, 0) == 0; ++i)
    if (fields[i].type != "object") out.push_back(&fields[i]);
  return out;
}

bool edit_array(const std::vector<scene::FieldInfo>& fields, size_t a, ordered_json& array) {
  const scene::FieldInfo& f = fields[a];
  bool changed = false;
  if (!array.is_array()) return false;
  const std::string prefix = f.path + "[].";
  const auto elements = element_fields(fields, a);
  for (size_t i = 0; i < array.size(); ++i) {
    ImGui::PushID(int(i));
    const std::string title = f.path.substr(f.path.rfind('.') + 1) + "[" + std::to_string(i) + "]";
    const bool open = ImGui::TreeNode(title.c_str());
    if (array.size() > f.min_elements) {
      ImGui::SameLine();
      if (ImGui::SmallButton("remove")) {
        array.erase(i);
        ImGui::PopID();
        if (open) ImGui::TreePop();
        return true;
      }
    }
    if (open) {
      for (const scene::FieldInfo* e : elements) {
        const std::string sub = e->path.substr(prefix.size());
        const auto ptr = pointer(sub);
        if (!array[i].contains(ptr)) continue;
        changed |= edit_value(*e, sub, array[i][ptr]);
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (array.size() < f.max_elements && ImGui::SmallButton(("add to " + f.path).c_str())) {
    // A copy of the last element, or the format's default element, with every field present so that
    // required ones (an object's file) can be typed in.
    ordered_json element = array.empty() ? ordered_json::object() : array.back();
    if (array.empty())
      for (const scene::FieldInfo* e : elements) {
        if (e->default_value.empty()) continue;
        ordered_json value = ordered_json::parse(e->default_value, nullptr, false);
        element[pointer(e->path.substr(prefix.size()))] =
            value.is_discarded() ? ordered_json(e->default_value) : value;
      }
    array.push_back(element);
    changed = true;
  }
  return changed;
}

}  // namespace

std::string safe_dump(const nlohmann::ordered_json& value) {
  return value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

Result<void> replace_scene(scene::Scene& scene, const nlohmann::json& document) {
  auto parsed = scene::parse_scene(document, scene.source.empty() ? "(panel)" : scene.source.string());
  if (!parsed) return parsed.error();
  parsed->source = scene.source;
  scene = std::move(*parsed);
  return {};
}

Result<void> edit_scene(scene::Scene& scene, const std::string& assignment) {
  // File paths stay as the scene holds them (already resolved against its folder).
  nlohmann::json document = nlohmann::json::parse(safe_dump(scene::scene_to_json(scene, {})));
  if (auto r = scene::apply_override(document, assignment); !r) return r.error();
  return replace_scene(scene, document);
}

bool ParameterPanel::draw(scene::Scene& scene) {
  const std::vector<scene::FieldInfo> fields = scene::scene_fields(scene);
  // The values come with the field rows: one pass over the scene per frame, not two.
  ordered_json document = pending_.is_null() ? scene::fields_to_json(fields) : pending_;
  bool edited = false;
  bool section_open = false;
  for (size_t i = 0; i < fields.size(); ++i) {
    const scene::FieldInfo& f = fields[i];
    if (f.path.find("[]") != std::string::npos) continue;  // drawn with their array
    const bool top_level = f.path.find('.') == std::string::npos;
    if (top_level) {
      if (f.type == "object" || f.type == "array of objects") {
        section_open = ImGui::CollapsingHeader(f.path.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", ascii(f.doc).c_str());
        if (!section_open || f.type == "object") continue;
      } else {
        section_open = ImGui::CollapsingHeader("other");  // top-level values such as time_s
        if (!section_open) continue;
      }
    }
    if (!section_open || f.type == "object") continue;
    ImGui::PushID(f.path.c_str());
    const auto ptr = pointer(f.path);
    if (f.type == "array of objects") {
      if (!document.contains(ptr)) document[ptr] = ordered_json::parse(f.default_value);
      edited |= edit_array(fields, i, document[ptr]);
    } else if (document.contains(ptr)) {
      const std::string label = top_level ? f.path : f.path.substr(f.path.find('.') + 1);
      edited |= edit_value(f, label, document[ptr]);
    }
    ImGui::PopID();
  }
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 90, 255));
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("revert the invalid edit")) discard_pending();
  }
  if (!edited) return false;
  if (auto r = replace_scene(scene, nlohmann::json::parse(safe_dump(document))); !r) {
    pending_ = document;
    error_ = r.error().message;
    return false;
  }
  discard_pending();
  return true;
}

}  // namespace lagoon::demo
