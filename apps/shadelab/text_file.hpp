// A whole file as text, for the command's and the lab's readers of scenes, manifests and
// rows.json. Nothing else: parsing and messages are the callers'.
#pragma once

#include <optional>
#include <string>

namespace shadelab::cli {

/// The file's contents, or nothing when it cannot be opened.
std::optional<std::string> read_text_file(const std::string& path);

}  // namespace shadelab::cli
