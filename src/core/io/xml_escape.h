// Text for XML (SVG) documents.
#pragma once

#include <string>

namespace autoblock {

// Inputs:  text. Outputs: text with &, <, > and " written as entities, safe in element content and
//          in double-quoted attributes.
std::string xml_escape(const std::string& text);

}  // namespace autoblock
