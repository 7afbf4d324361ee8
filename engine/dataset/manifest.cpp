#include "dataset/manifest.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "core/bounded_file.h"
#include "io/atomic_file.h"
#include "io/json_limits.h"
#include "io/sha256.h"

namespace lagoon::dataset {

using io::json_limit_exceeded;
using io::JsonLimits;
using io::os_error_message;
using io::sha256_file;
using io::write_text_atomic;

namespace {

using nlohmann::json;

constexpr int kVersion = 1;
// A manifest line is a few hundred bytes (a frame with eight files under 2 KB); far longer is not ours.
constexpr size_t kMaxLineBytes = size_t{1} << 20;
constexpr JsonLimits kLineLimits{.max_depth = 16, .max_array_length = 4096, .max_string_bytes = 1 << 16};

json header_json(const Manifest& m) {
  return {{"lagoon_dataset_manifest", kVersion},
          {"frames", m.frames},
          {"shard", {m.shard_index, m.shard_count}},
          {"run", m.run}};
}

json frame_json(const ManifestFrame& f) {
  json files = json::array();
  for (const ManifestFile& file : f.files)
    files.push_back({{"name", file.name}, {"sha256", file.sha256}, {"bytes", file.bytes}});
  return {{"frame", f.frame}, {"time_s", f.time_s}, {"device", f.device}, {"files", files}};
}

// nullopt when `j` is not a frame line (the caller names the line).
std::optional<ManifestFrame> frame_from_json(const json& j) {
  if (!j.is_object() || !j.contains("frame") || !j["frame"].is_number_integer() || !j.contains("files") ||
      !j["files"].is_array())
    return std::nullopt;
  ManifestFrame f{
      .frame = j["frame"].get<long long>(),
      .time_s = j.value("time_s", 0.0),
      .device = j.contains("device") && j["device"].is_string() ? j["device"].get<std::string>() : ""};
  for (const json& file : j["files"]) {
    if (!file.is_object() || !file.contains("name") || !file["name"].is_string() ||
        !file.contains("sha256") || !file["sha256"].is_string() || !file.contains("bytes") ||
        !file["bytes"].is_number_unsigned())
      return std::nullopt;
    const std::string name = file["name"];
    // Names are plain file names beside the manifest: never a path that leaves the folder.
    if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..")
      return std::nullopt;
    f.files.push_back({name, file["sha256"], file["bytes"].get<uintmax_t>()});
  }
  return f;
}

Result<void> header_from_json(const json& j, Manifest& m) {
  if (!j.is_object() || j.value("lagoon_dataset_manifest", 0) != kVersion || !j.contains("frames") ||
      !j["frames"].is_number_integer() || !j.contains("shard") || !j["shard"].is_array() ||
      j["shard"].size() != 2 || !j["shard"][0].is_number_integer() || !j["shard"][1].is_number_integer() ||
      !j.contains("run"))
    return Error{"is not a Lagoon dataset manifest (version " + std::to_string(kVersion) + ")"};
  m.frames = j["frames"];
  m.shard_index = j["shard"][0];
  m.shard_count = j["shard"][1];
  m.run = j["run"];
  if (m.frames < 1 || m.shard_count < 1 || m.shard_index < 0 || m.shard_index >= m.shard_count)
    return Error{"has frames " + std::to_string(m.frames) + " and shard " + std::to_string(m.shard_index) +
                 "/" + std::to_string(m.shard_count) + ", which no run writes"};
  return {};
}

std::optional<json> parse_line(const std::string& line) {
  if (line.size() > kMaxLineBytes || json_limit_exceeded(line, kLineLimits)) return std::nullopt;
  json j = json::parse(line, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return std::nullopt;
  return j;
}

}  // namespace

Result<Manifest> read_manifest(const std::filesystem::path& path) {
  // A manifest is a line per frame (about 300 bytes): 1 GiB is millions of frames. Checked before it is
  // opened (core/bounded_file.h), so a FIFO or device named as one is refused, not read for ever.
  if (const FileCheck check = check_file_to_read(path, std::uintmax_t{1} << 30); !check)
    return Error{"cannot read the manifest " + path.string() + ": it " + check.reason};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{os_error_message("cannot open", path, errno)};
  Manifest m;
  std::string line;
  long long number = 0;
  bool header = true;
  while (std::getline(in, line)) {
    ++number;
    const bool complete = !in.eof();  // getline stopped at a newline, not at the end of the file
    const std::optional<json> j = parse_line(line);
    if (!complete) {  // a last line without its newline: cut off by a kill while appending
      m.cut_off_tail = true;
      break;
    }
    const std::string where = path.string() + ":" + std::to_string(number) + ": ";
    if (!j)
      return Error{where + "not a JSON line (the manifest is damaged; delete it and render the shard again)"};
    if (header) {
      if (Result<void> ok = header_from_json(*j, m); !ok) return Error{where + ok.error().message};
      header = false;
      continue;
    }
    std::optional<ManifestFrame> frame = frame_from_json(*j);
    if (!frame || frame->frame < 0 || frame->frame >= m.frames)
      return Error{where +
                   "not a frame entry of this manifest (the manifest is damaged; delete it and render "
                   "the shard again)"};
    m.entries.push_back(std::move(*frame));
  }
  if (header) return Error{path.string() + ": is empty or has no complete header line"};
  return m;
}

Result<ManifestFile> describe_file(const std::filesystem::path& path, const std::string& name) {
  std::error_code ec;
  const uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) return Error{os_error_message("cannot read", path, ec.value())};
  Result<std::string> sha = sha256_file(path);
  if (!sha) return sha.error();
  return ManifestFile{name, *sha, bytes};
}

Result<ManifestWriter> ManifestWriter::create(const std::filesystem::path& path, const Manifest& manifest) {
  std::string text = header_json(manifest).dump() + "\n";
  for (const ManifestFrame& f : manifest.entries) text += frame_json(f).dump() + "\n";
  if (Result<void> ok = write_text_atomic(path, text); !ok) return ok.error();
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) return Error{os_error_message("cannot open", path, errno)};
  return ManifestWriter(path, fd);
}

ManifestWriter::ManifestWriter(ManifestWriter&& other) noexcept
    : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)) {}

ManifestWriter::~ManifestWriter() {
  if (fd_ >= 0) ::close(fd_);
}

Result<void> ManifestWriter::append(const ManifestFrame& frame) {
  const std::string line = frame_json(frame).dump() + "\n";
  size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Error{os_error_message("cannot write", path_, errno)};
    done += size_t(n);
  }
  if (::fsync(fd_) != 0) return Error{os_error_message("cannot sync", path_, errno)};
  return {};
}

std::string entry_mismatch(const std::filesystem::path& folder, const ManifestFrame& frame) {
  for (const ManifestFile& file : frame.files) {
    std::error_code ec;
    const std::filesystem::path path = folder / file.name;
    const uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (ec) return path.string() + " is missing";
    if (bytes != file.bytes)
      return path.string() + " has " + std::to_string(bytes) + " bytes, the manifest " +
             std::to_string(file.bytes);
    Result<std::string> sha = sha256_file(path);
    if (!sha) return sha.error().message;
    if (*sha != file.sha256) return path.string() + " does not match its SHA-256 in the manifest";
  }
  return "";
}

DatasetReport verify_dataset(const std::filesystem::path& folder) {
  DatasetReport report;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    report.problems.push_back(folder.string() + ": not a folder; name the folder a render wrote into");
    return report;
  }
  static const std::regex kName(R"((.+)\.shard-([0-9]+)-of-([0-9]+)\.jsonl)");
  std::map<std::string, std::vector<std::pair<std::filesystem::path, Manifest>>> sets;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = item.path().filename().string();
    std::smatch match;
    if (!std::regex_match(name, match, kName)) continue;
    Result<Manifest> m = read_manifest(item.path());
    if (!m) {
      report.problems.push_back(m.error().message);
      continue;
    }
    if (m->cut_off_tail)
      report.problems.push_back(item.path().string() +
                                ": its last line is cut off: the shard was stopped while "
                                "writing; run it again to finish");
    sets[match[1]].emplace_back(item.path(), std::move(*m));
  }
  if (sets.empty() && report.problems.empty())
    report.problems.push_back(folder.string() +
                              ": no manifest (OUT.shard-I-of-N.jsonl) found; was it written "
                              "by lagoon render --frames or --shard?");
  for (auto& [stem, shards] : sets) {
    ++report.sets;
    const Manifest& first = shards.front().second;
    std::set<long long> shard_seen;
    std::map<long long, std::string> listed;  // frame -> manifest that lists it
    for (const auto& [path, m] : shards) {
      if (m.run != first.run || m.frames != first.frames || m.shard_count != first.shard_count) {
        report.problems.push_back(path.string() + ": written by another run than " +
                                  shards.front().first.filename().string() +
                                  " (scene, options or shard count differ); render the set again into an "
                                  "empty folder");
        continue;
      }
      shard_seen.insert(m.shard_index);
      for (const ManifestFrame& f : m.entries) {
        if (f.frame % m.shard_count != m.shard_index)
          report.problems.push_back(path.string() + ": lists frame " + std::to_string(f.frame) +
                                    ", which belongs to another shard");
        if (auto [it, fresh] = listed.emplace(f.frame, path.filename().string()); !fresh) {
          report.problems.push_back(path.string() + ": lists frame " + std::to_string(f.frame) +
                                    " again (also in " + it->second + ")");
          continue;
        }
        if (std::string why = entry_mismatch(folder, f); !why.empty()) {
          report.problems.push_back("frame " + std::to_string(f.frame) + ": " + why +
                                    "; render its shard again (finished frames are kept)");
          continue;
        }
        ++report.frames;
        for (const ManifestFile& file : f.files) report.bytes += file.bytes, ++report.files;
      }
    }
    for (long long s = 0; s < first.shard_count; ++s)
      if (!shard_seen.count(s))
        report.problems.push_back(stem + ": shard " + std::to_string(s) + " of " +
                                  std::to_string(first.shard_count) + " has no manifest; run it (--shard " +
                                  std::to_string(s) + "/" + std::to_string(first.shard_count) + ")");
    long long missing = 0, first_missing = -1;
    for (long long f = 0; f < first.frames; ++f)
      if (!listed.count(f) && shard_seen.count(f % first.shard_count)) {
        if (first_missing < 0) first_missing = f;
        ++missing;
      }
    if (missing > 0)
      report.problems.push_back(
          stem + ": " + std::to_string(missing) + " of " + std::to_string(first.frames) +
          " frames are not finished (the first is frame " + std::to_string(first_missing) + ", shard " +
          std::to_string(first_missing % first.shard_count) + "); run those shards again to finish them");
  }
  return report;
}

}  // namespace lagoon::dataset
