#pragma once
/// The file access assimp gets while it imports one asset: the asset itself, and the files it refers
/// to only inside its folder (asset_reference.h), each read whole under the size limit.
///
/// Design note: assimp opens the files an asset names (a .gltf's buffers, for example) through an
/// IOSystem, joining the asset's folder and the name as the asset wrote it. This one answers only for
/// the asset's own path and for names under its folder that pass resolve_reference; anything else (an
/// absolute name, `..`, a link out of the folder, a device, a FIFO, a file past the limit, or more
/// bytes in all than one mesh file may hold) is not opened, and the first refusal is kept so that the
/// import fails with a message naming the reference, even where assimp would carry on without it.

#include <assimp/IOSystem.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace shatter {

class ConfinedIOSystem final : public Assimp::IOSystem {
 public:
  /// For importing the file `asset`; `max_bytes` limits each file and all the references together.
  /// An empty `asset` (an asset held in memory) may open no file at all.
  ConfinedIOSystem(const std::filesystem::path& asset, std::uint64_t max_bytes);

  bool Exists(const char* file) const override;
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
  void Close(Assimp::IOStream* stream) override;

  /// The first reference refused, as one line ("buffer '../x.bin' refused: ..."), or empty.
  [[nodiscard]] const std::string& refusal() const { return refusal_; }

 private:
  /// The reference part of `file` (what follows the asset's folder); `outside` is set when `file`
  /// does not start with the folder at all.
  std::string reference_of(const std::string& file, bool& outside) const;

  std::string asset_;       ///< the asset's path, as given to assimp
  std::string folder_;      ///< its folder with a trailing '/' ("" for the working folder)
  std::uint64_t max_bytes_;
  std::uint64_t read_bytes_ = 0;  ///< bytes of references read so far
  std::string refusal_;
};

}  // namespace shatter
