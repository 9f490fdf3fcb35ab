// --set overrides ("key.path[2].x=value") applied to a located JSON tree before validation.
// Private to the scene reader. It only edits the tree: validation comes after, and problems
// are diagnostics, never prints or exceptions.
#pragma once

#include <string>

#include "scene/json_tree.hpp"

namespace shadelab::detail {

/// Applies "key.path[2].x=value" to `root`: the value is JSON, or else taken as a bare string;
/// missing objects (and arrays, before an index) are created; an index equal to an array's
/// length appends. Values set this way have line 0: they are reported against file "--set".
/// On a malformed assignment or a path that cannot be followed, adds a diagnostic located at
/// "--set" and returns false.
bool apply_override(JsonValue& root, const std::string& assignment, Diagnostics& diags);

}  // namespace shadelab::detail
