// Batches split across processes or machines (docs/scale-out.md): `--shard I/N` makes sweep,
// animate or gallery render only its share of the batch's parts (part k belongs to shard
// k mod N + 1) into OUTPUT.parts/, skipping parts already there, so a shard run again resumes;
// each shard also writes OUTPUT.parts/manifest.json, the same from every shard (the command and
// its arguments). `shadelab merge OUTPUT` then assembles the parts into OUTPUT, byte for byte
// what the command alone would have written. Nothing here renders.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shadelab/image.hpp"

namespace shadelab::cli {

struct Shard {
  int index = 0, count = 0;  ///< shard `index` of `count` (1-based); count 0: not sharded
  bool active() const { return count > 0; }
  /// Whether part `part` (0-based) is this shard's to render.
  bool owns(std::size_t part) const { return !active() || int(part % std::size_t(count)) == index - 1; }
};

/// Parses "I/N" (1 <= I <= N <= 100000). False and `error` when malformed.
bool parse_shard(const std::string& text, Shard& out, std::string* error);

/// OUTPUT.parts: where the shards of the batch that makes `output` put their parts.
std::string parts_dir(const std::string& output);

/// The file of part `part` of that batch (`extension` with its dot).
std::string part_path(const std::string& output, std::size_t part, const std::string& extension = ".png");

/// Creates the parts folder and writes the manifest there atomically. False and `error`.
bool write_manifest(const std::string& output, const nlohmann::json& manifest, std::string* error);

/// The batch's manifest, or nothing and `error` (no parts folder, not a manifest).
std::optional<nlohmann::json> read_manifest(const std::string& output, std::string* error);

/// The parts of `count` (with `extension`) not yet written, by number.
std::vector<std::size_t> missing_parts(const std::string& output, std::size_t count,
                                       const std::string& extension = ".png");

/// Part `part` read back (a PNG the shard wrote). False and `error`.
bool read_part(const std::string& output, std::size_t part, Image& image, std::string* error);

/// Writes one picture as part `part`, atomically (a part that exists is complete).
bool write_part(const std::string& output, std::size_t part, const Image& image, std::string* error);

}  // namespace shadelab::cli
