#include "io/npy_stream.h"

#include <string>

#include "io/npy.h"

namespace lagoon::io {

Result<NpyStreamWriter> NpyStreamWriter::create(const std::filesystem::path& path,
                                                std::span<const size_t> shape) {
  const std::string where = "cannot write NPY " + path.string() + ": ";
  if (shape.empty()) return make_error(where + "a streamed array needs at least one axis");
  Result<std::string> header = npy_header(shape);
  if (!header) return make_error(where + header.error().message);
  size_t slab = 1;
  for (size_t d : shape.subspan(1)) slab *= d;  // cannot overflow: npy_header checked the whole product
  Result<AtomicFile> file = AtomicFile::create(path);
  if (!file) return file.error();
  if (Result<void> r = file->write(std::as_bytes(std::span(*header))); !r) return r.error();
  return NpyStreamWriter(std::move(*file), std::vector<size_t>(shape.begin(), shape.end()), slab);
}

Result<void> NpyStreamWriter::append(std::span<const float> slab) {
  const std::string where = "cannot write NPY " + file_.target().string() + ": ";
  if (slab.size() != slab_size_) {
    return make_error(where + "a slab holds " + std::to_string(slab_size_) + " values, not " +
                      std::to_string(slab.size()));
  }
  if (written_ == shape_[0])
    return make_error(where + "all " + std::to_string(shape_[0]) + " slabs are already written");
  if (Result<void> r = write_npy_values(file_, slab); !r) return r;
  ++written_;
  return {};
}

Result<void> NpyStreamWriter::commit() {
  if (written_ != shape_[0]) {
    return make_error("cannot write NPY " + file_.target().string() + ": " + std::to_string(written_) +
                      " of " + std::to_string(shape_[0]) + " slabs were written");
  }
  return file_.commit();
}

Result<uint64_t> npy_file_bytes(std::span<const size_t> shape) {
  Result<std::string> header = npy_header(shape);
  if (!header) return header.error();
  uint64_t count = 1;
  for (size_t d : shape) count *= d;  // npy_header refused shapes whose byte count overflows
  return uint64_t(header->size()) + 4 * count;
}

}  // namespace lagoon::io
