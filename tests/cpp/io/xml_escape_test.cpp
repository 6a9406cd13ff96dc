#include <catch2/catch.hpp>

#include "core/io/xml_escape.h"

using namespace autoblock;

TEST_CASE("xml_escape writes the markup characters as entities", "[io][svg]") {
  CHECK(xml_escape("shape_0003.brep - policy sac-mesh") == "shape_0003.brep - policy sac-mesh");
  CHECK(xml_escape("a < b && c > \"d\"") == "a &lt; b &amp;&amp; c &gt; &quot;d&quot;");
  CHECK(xml_escape("") == "");
}
