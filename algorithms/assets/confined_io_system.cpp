#include "algorithms/assets/confined_io_system.h"

#include "algorithms/core/asset_reference.h"
#include "algorithms/core/bounded_read.h"

#include <assimp/IOStream.hpp>

#include <algorithm>
#include <cstring>
#include <utility>

namespace shatter {
namespace fs = std::filesystem;

namespace {

/// A file read whole, served from memory.
class BufferStream final : public Assimp::IOStream {
 public:
  explicit BufferStream(std::string bytes) : bytes_(std::move(bytes)) {}
  size_t Read(void* buffer, size_t size, size_t count) override {
    if (size == 0 || count == 0) return 0;
    const std::size_t left = bytes_.size() - at_;
    const std::size_t items = std::min(count, left / size);
    std::memcpy(buffer, bytes_.data() + at_, items * size);
    at_ += items * size;
    return items;
  }
  size_t Write(const void*, size_t, size_t) override { return 0; }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    const std::size_t base = origin == aiOrigin_SET ? 0 : origin == aiOrigin_CUR ? at_ : bytes_.size();
    if (offset > bytes_.size() - base) return aiReturn_FAILURE;
    at_ = base + offset;
    return aiReturn_SUCCESS;
  }
  size_t Tell() const override { return at_; }
  size_t FileSize() const override { return bytes_.size(); }
  void Flush() override {}

 private:
  std::string bytes_;
  std::size_t at_ = 0;
};

}  // namespace

ConfinedIOSystem::ConfinedIOSystem(const fs::path& asset, std::uint64_t max_bytes)
    : asset_(asset.string()), max_bytes_(max_bytes) {
  const fs::path folder = asset.parent_path();
  folder_ = folder.empty() ? std::string() : folder.string() + "/";
}

std::string ConfinedIOSystem::reference_of(const std::string& file, bool& outside) const {
  outside = false;
  if (folder_.empty()) return file;
  if (file.compare(0, folder_.size(), folder_) == 0) return file.substr(folder_.size());
  outside = true;
  return file;
}

bool ConfinedIOSystem::Exists(const char* file) const {
  if (file == nullptr || asset_.empty()) return false;
  if (file == asset_) return true;
  bool outside = false;
  const std::string reference = reference_of(file, outside);
  if (outside) return false;
  const fs::path folder = folder_.empty() ? fs::path(".") : fs::path(folder_);
  return resolve_reference(folder, reference, max_bytes_, "reference").ok();
}

Assimp::IOStream* ConfinedIOSystem::Open(const char* file, const char* mode) {
  if (file == nullptr) return nullptr;
  if (mode == nullptr || std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr ||
      std::strchr(mode, '+') != nullptr) {
    if (refusal_.empty()) refusal_ = std::string("'") + file + "': assimp asked to write it; nothing is written";
    return nullptr;
  }
  const std::string name(file);
  if (asset_.empty()) {  // an asset held in memory refers to no file at all
    if (refusal_.empty()) refusal_ = "reference '" + name.substr(0, 200) + "' refused: an asset read from memory may name no file";
    return nullptr;
  }
  if (name == asset_) {
    Result<std::string> bytes = read_file_bounded(name, max_bytes_, "mesh file");
    return bytes ? new BufferStream(std::move(*bytes)) : nullptr;
  }
  bool outside = false;
  const std::string reference = reference_of(name, outside);
  const fs::path folder = folder_.empty() ? fs::path(".") : fs::path(folder_);
  Result<fs::path> resolved = outside ? Result<fs::path>(Error{"reference '" + name.substr(0, 200) +
                                                               "' refused: outside the asset's folder"})
                                      : resolve_reference(folder, reference, max_bytes_, "reference");
  if (!resolved) {
    if (refusal_.empty()) refusal_ = resolved.error().message;
    return nullptr;
  }
  Result<std::string> bytes = read_file_bounded(*resolved, max_bytes_ - std::min(max_bytes_, read_bytes_), "reference");
  if (!bytes) {
    if (refusal_.empty())
      refusal_ = "reference '" + reference.substr(0, 200) + "' refused: the asset's references hold more than " +
                 std::to_string(max_bytes_) + " bytes in all";
    return nullptr;
  }
  read_bytes_ += bytes->size();
  return new BufferStream(std::move(*bytes));
}

void ConfinedIOSystem::Close(Assimp::IOStream* stream) { delete stream; }

}  // namespace shatter
