// JPEG through libjpeg-turbo, which checks the Huffman tables and the markers itself (the two guards Lagoon
// kept in front of stb_image are no longer needed). Its errors end the decoding by longjmp: everything C++
// lives in a heap-allocated Decoder made before setjmp, so the jump skips no destructor.
// jpeglib.h uses FILE and size_t without including them: <cstdio> first, in a block of its own.
#include <cstdio>

#include <jpeglib.h>

#include <csetjmp>
#include <cstring>
#include <memory>
#include <vector>

#include "io/image_decode.h"

namespace lagoon::io {
namespace {

// A progressive JPEG may hold any number of scans, each a full pass over the coefficients: a small file
// of thousands of scans takes minutes. libjpeg-turbo's own fuzzers stop at 500; so does Lagoon.
constexpr int kMaxScans = 500;

struct Decoder {
  jpeg_decompress_struct cinfo{};
  jpeg_error_mgr errors{};
  jpeg_progress_mgr progress{};
  std::jmp_buf jump{};
  char message[JMSG_LENGTH_MAX] = "";
  bool created = false;
  std::vector<uint8_t> cmyk_row;
  ~Decoder() {
    if (created) jpeg_destroy_decompress(&cinfo);
  }
};

Decoder& decoder_of(j_common_ptr c) {
  return *static_cast<Decoder*>(c->client_data);
}

[[noreturn]] void on_error(j_common_ptr c) {
  Decoder& d = decoder_of(c);
  (*c->err->format_message)(c, d.message);
  std::longjmp(d.jump, 1);
}

// Warnings (corrupt data the decoder can go past, an early end) and traces are not printed: the image
// decodes as well as it can, as in every viewer.
void on_message(j_common_ptr, int) {}

void on_progress(j_common_ptr c) {
  auto* cinfo = reinterpret_cast<j_decompress_ptr>(c);
  if (cinfo->input_scan_number > kMaxScans) {
    Decoder& d = decoder_of(c);
    std::snprintf(d.message, sizeof d.message, "more than %d progressive scans", kMaxScans);
    std::longjmp(d.jump, 1);
  }
}

// Adobe's CMYK JPEGs store the inks inverted; others store them as they are.
void cmyk_to_rgba(const uint8_t* cmyk, uint8_t* rgba, uint32_t width, bool inverted) {
  for (uint32_t x = 0; x < width; ++x, cmyk += 4, rgba += 4) {
    const int k = inverted ? cmyk[3] : 255 - cmyk[3];
    for (int i = 0; i < 3; ++i) {
      const int ink = inverted ? cmyk[i] : 255 - cmyk[i];
      rgba[i] = uint8_t((ink * k + 127) / 255);
    }
    rgba[3] = 255;
  }
}

}  // namespace

Result<Image8> decode_jpeg(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side) {
  if (sniff_image_format(bytes) != ImageFormat::kJpeg)
    return make_error(where + ": not a JPEG file (wrong signature)");
  auto d = std::make_unique<Decoder>();
  auto out = std::make_unique<Image8>();
  jpeg_decompress_struct& cinfo = d->cinfo;
  cinfo.err = jpeg_std_error(&d->errors);
  d->errors.error_exit = on_error;
  d->errors.emit_message = on_message;
  d->progress.progress_monitor = on_progress;
  if (setjmp(d->jump))
    return make_error(where + ": cannot decode the JPEG (libjpeg-turbo: " + d->message + ")");
  jpeg_create_decompress(&cinfo);
  d->created = true;
  cinfo.client_data = d.get();
  cinfo.progress = &d->progress;
  jpeg_mem_src(&cinfo, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&cinfo, TRUE);
  if (cinfo.image_width == 0 || cinfo.image_height == 0 || cinfo.image_width > max_side ||
      cinfo.image_height > max_side)
    return make_error(image_too_large(where, cinfo.image_width, cinfo.image_height, max_side));
  const bool cmyk = cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK;
  cinfo.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
  jpeg_start_decompress(&cinfo);
  out->width = cinfo.output_width;
  out->height = cinfo.output_height;
  out->rgba.resize(size_t{out->width} * out->height * 4);
  if (cmyk) d->cmyk_row.resize(size_t{out->width} * 4);
  while (cinfo.output_scanline < cinfo.output_height) {
    uint8_t* rgba = out->rgba.data() + size_t{cinfo.output_scanline} * out->width * 4;
    JSAMPROW row = cmyk ? d->cmyk_row.data() : rgba;
    if (jpeg_read_scanlines(&cinfo, &row, 1) != 1) break;  // a suspending source cannot happen in memory
    if (cmyk) cmyk_to_rgba(d->cmyk_row.data(), rgba, out->width, cinfo.saw_Adobe_marker);
  }
  jpeg_finish_decompress(&cinfo);
  return std::move(*out);
}

}  // namespace lagoon::io
