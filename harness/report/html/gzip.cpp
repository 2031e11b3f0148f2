#include "harness/report/html/gzip.h"

#include <zlib.h>

#include <limits>

namespace shatter {

Result<std::string> gzip(std::string_view bytes) {
  z_stream stream{};
  // windowBits 15 + 16: a gzip header and trailer rather than zlib's.
  if (deflateInit2(&stream, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    return Error{"gzip: zlib could not start"};
  std::string out(deflateBound(&stream, static_cast<uLong>(bytes.size())) + 32, '\0');
  int status = Z_OK;
  std::size_t done = 0;
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(std::min<std::size_t>(out.size(), std::numeric_limits<uInt>::max()));
  // Fed in pieces of at most 1 GiB (avail_in is 32 bits).
  while (status == Z_OK) {
    const std::size_t piece = std::min<std::size_t>(bytes.size() - done, 1u << 30);
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + done));
    stream.avail_in = static_cast<uInt>(piece);
    done += piece;
    status = deflate(&stream, done == bytes.size() ? Z_FINISH : Z_NO_FLUSH);
    if (status == Z_BUF_ERROR || (status == Z_OK && stream.avail_out == 0)) break;
  }
  const std::size_t written = stream.total_out;
  deflateEnd(&stream);
  if (status != Z_STREAM_END) return Error{"gzip: zlib could not compress the data"};
  out.resize(written);
  return out;
}

}  // namespace shatter
