#include "core/mesh/conformal_merge.h"

#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/geometry/occt_properties.h"

namespace autoblock {

ConformalBlocks conformal_merge(const std::vector<TopoDS_Face>& blocks, double fuzzy) {
  if (blocks.empty()) throw std::runtime_error("conformal_merge: no blocks");
  if (blocks.size() == 1) {  // a rectangular face: nothing to merge (the general fuse wants two)
    ConformalBlocks single;
    BRep_Builder compound_builder;
    compound_builder.MakeCompound(single.compound);
    compound_builder.Add(single.compound, blocks[0]);
    single.faces = blocks;
    return single;
  }
  TopTools_ListOfShape arguments;
  for (const TopoDS_Face& block : blocks) arguments.Append(block);
  BRepAlgoAPI_BuilderAlgo builder;
  builder.SetArguments(arguments);
  builder.SetRunParallel(false);
  builder.SetNonDestructive(true);  // the input faces stay untouched
  if (fuzzy > 0) builder.SetFuzzyValue(fuzzy);
  try {
    builder.Build();
  } catch (const Standard_Failure& e) {
    throw std::runtime_error(std::string("conformal merge: OpenCASCADE failed: ") + e.GetMessageString());
  }
  if (!builder.IsDone() || builder.HasErrors()) throw std::runtime_error("conformal merge: general fuse failed");

  ConformalBlocks result;
  BRep_Builder compound_builder;
  compound_builder.MakeCompound(result.compound);
  for (size_t b = 0; b < blocks.size(); ++b) {
    const TopTools_ListOfShape& images = builder.Modified(blocks[b]);
    TopoDS_Face face;
    if (images.IsEmpty()) {
      if (builder.IsDeleted(blocks[b])) throw std::runtime_error("conformal merge: a block vanished");
      face = blocks[b];  // untouched: it touches no other block
    } else {
      if (images.Extent() != 1 || images.First().ShapeType() != TopAbs_FACE) {
        throw std::runtime_error("conformal merge: block " + std::to_string(b + 1) + " came back as " +
                                 std::to_string(images.Extent()) + " shapes (blocks overlap?)");
      }
      face = TopoDS::Face(images.First());
    }
    const double area = occt_area(blocks[b]);
    double slack = 1e-9 * std::max(1.0, area);
    if (fuzzy > 0) {
      GProp_GProps lengths;
      BRepGProp::LinearProperties(blocks[b], lengths);
      slack += fuzzy * lengths.Mass();
    }
    if (std::fabs(occt_area(face) - area) > slack) {
      throw std::runtime_error("conformal merge: block " + std::to_string(b + 1) + " changed its area");
    }
    result.faces.push_back(face);
    compound_builder.Add(result.compound, face);
  }
  if (!occt_shape_valid(result.compound)) throw std::runtime_error("conformal merge: the result fails BRepCheck_Analyzer");
  return result;
}

}  // namespace autoblock
