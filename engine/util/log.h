// Warnings about input that raylab repaired or ignored: one line each on stderr, "raylab: warning: ...".
#pragma once

#include <functional>
#include <string>

namespace raylab {

void warn(const std::string& message);

// Where warnings go instead of stderr (a test that checks them, a viewer's message pane). An empty sink
// restores stderr. Returns the sink it replaces.
using WarningSink = std::function<void(const std::string& message)>;
WarningSink setWarningSink(WarningSink sink);

}  // namespace raylab
