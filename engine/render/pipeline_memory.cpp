#include "render/pipeline_memory.h"

#include <algorithm>

#include "render/cached_tables.h"
#include "render/device_key.h"
#include "scene/scene_io.h"

namespace lagoon::render {
namespace {

// The scene as it decides which pipelines its frames make: without what changes from frame to frame.
std::string scene_text(const scene::Scene& scene) {
  nlohmann::ordered_json doc = scene::scene_to_json(scene, {});
  doc.erase("time_s");
  doc.erase("camera");
  if (doc.contains("render")) {
    doc["render"].erase("width");
    doc["render"].erase("height");
  }
  return doc.dump();
}

std::vector<std::string> split_lines(const std::vector<char>& text) {
  std::vector<std::string> lines;
  std::string line;
  for (char c : text) {
    if (c != '\n') {
      line += c;
    } else if (!line.empty()) {
      lines.push_back(std::move(line));
      line.clear();
    }
  }
  return lines;
}

}  // namespace

PipelineMemory::PipelineMemory(const vk::Context& ctx, const scene::Scene& scene)
    : key_(table_key("pipelines")) {
  add_device(key_, ctx);
  key_.add("scene", scene_text(scene));
  if (auto bytes = io::ResultCache::from_environment().load(key_)) {
    io::ByteReader in(*bytes);
    const std::vector<char> text = in.get_vector<char>(kMaxKeys * 1024);
    if (in.complete()) remembered_ = split_lines(text);
    if (remembered_.size() > kMaxKeys) remembered_.clear();  // not ours
  }
  made_seen_ = ctx.pipelines().used_count();
}

void PipelineMemory::update(const vk::Context& ctx) {
  const size_t made = ctx.pipelines().used_count();
  if (made == made_seen_) return;
  for (std::string& key : ctx.pipelines().used_keys(made_seen_))
    if (made_.size() < kMaxKeys && std::find(made_.begin(), made_.end(), key) == made_.end())
      made_.push_back(std::move(key));
  made_seen_ = made;
  if (made_ == remembered_) return;
  std::vector<char> text;
  for (const std::string& key : made_) {
    text.insert(text.end(), key.begin(), key.end());
    text.push_back('\n');
  }
  io::ByteWriter out;
  out.put_vector(text);
  io::ResultCache::from_environment().store(key_, out.bytes());
}

}  // namespace lagoon::render
