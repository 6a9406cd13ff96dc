#include "core/solid/prism_blocks.h"

#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <stdexcept>
#include <string>

namespace autoblock {

PrismBlocks prism_blocks(const ConformalBlocks& blocks, const Placement& frame, const gp_Vec& sweep) {
  // The whole compound moves at once, so that shared edges stay shared.
  TopoDS_Shape cap = blocks.compound;
  std::vector<TopoDS_Shape> faces(blocks.faces.begin(), blocks.faces.end());
  if (!frame.identity()) {
    BRepBuilderAPI_Transform move(blocks.compound, frame.to_model(), true);
    if (!move.IsDone()) throw std::runtime_error("prism blocks: OpenCASCADE cannot move the blocks into the model");
    cap = move.Shape();
    for (TopoDS_Shape& f : faces) f = move.ModifiedShape(f);
  }
  BRepPrimAPI_MakePrism prism(cap, sweep, true);
  if (!prism.IsDone()) throw std::runtime_error("prism blocks: OpenCASCADE's prism failed");
  PrismBlocks out;
  BRep_Builder builder;
  builder.MakeCompound(out.compound);
  for (size_t b = 0; b < faces.size(); ++b) {
    const TopTools_ListOfShape& made = prism.Generated(faces[b]);
    if (made.Extent() != 1 || made.First().ShapeType() != TopAbs_SOLID) {
      throw std::runtime_error("prism blocks: block " + std::to_string(b + 1) + " did not give one solid");
    }
    out.solids.push_back(TopoDS::Solid(made.First()));
    builder.Add(out.compound, made.First());
  }
  return out;
}

}  // namespace autoblock
