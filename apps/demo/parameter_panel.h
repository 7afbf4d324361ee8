// An editor for every field of the scene, generated from the scene format's own field table
// (scene::scene_fields): the same declarations that validate files and write docs/scene-format.md give
// each widget its type, range, choices and tooltip, so a new scene field appears here by itself. Edits go
// through the loader (parse_scene), so the panel cannot produce a scene the CLI would reject.
#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "scene/scene_io.h"

namespace lagoon::demo {

// JSON text of `value`; invalid UTF-8 (a file name from a non-UTF-8 folder) becomes U+FFFD instead of
// throwing.
std::string safe_dump(const nlohmann::ordered_json& value);

// Applies one "path=value" edit to `scene` through the loader. On failure `scene` is unchanged and the
// error is the loader's message (naming the field and the fix). Used by the panel and by --script.
Result<void> edit_scene(scene::Scene& scene, const std::string& assignment);
// Replaces `scene` with `document` if the loader accepts it; keeps scene.source.
Result<void> replace_scene(scene::Scene& scene, const nlohmann::json& document);

class ParameterPanel {
 public:
  // Draws one collapsing section per top-level block (camera, sun, ocean, ...). Returns true when `scene`
  // changed. An edit the loader rejects is kept in the panel, with the message, until it is fixed or
  // reverted; the scene keeps its last valid state meanwhile.
  bool draw(scene::Scene& scene);
  const std::string& error() const { return error_; }
  void discard_pending() {
    pending_ = nullptr;
    error_.clear();
  }

 private:
  nlohmann::ordered_json pending_;  // the document with an invalid edit, or null
  std::string error_;
};

}  // namespace lagoon::demo
