// exposed_default.h -- what the inspector says beside a parameter that the
// group being edited exposes. Inside a group, such a parameter's value is only
// the group's default: every instance of the group holds its own value (set on
// the instance's node), so an edit here changes no instance and, unexplained,
// looks like an edit that did nothing.
#pragma once

#include <cstddef>
#include <string>

#include "app/studio/editor/document.h"

namespace procex::studio {

// The note for parameter `param` of node `node` of doc.graph(), or "" when
// the graph edited is the recipe or the parameter is not exposed by it.
std::string exposed_default_note(const Document& doc, NodeId node, std::size_t param);

}  // namespace procex::studio
