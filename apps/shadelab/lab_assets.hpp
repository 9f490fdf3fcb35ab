// The lab page's files (web/lab/), embedded into the shadelab binary at build time by
// cmake/embed_assets.cmake; the server serves nothing else from disk.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace shadelab::cli {

struct LabAsset {
  std::string name;       ///< file name, e.g. "lab.js"
  std::string_view data;  ///< its bytes
  const char* mime;       ///< its content type
};

/// Every embedded file, index.html included.
const std::vector<LabAsset>& lab_assets();

}  // namespace shadelab::cli
