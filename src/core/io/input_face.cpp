#include "core/io/input_face.h"

#include "core/common/error.h"
#include "core/geometry/occt_face.h"
#include "core/io/face_selection.h"
#include "core/io/shape_file.h"

namespace autoblock {

InputFace load_input_face(const std::string& path, int face_number, const std::string& how_to_choose) {
  const TopoDS_Shape shape = read_shape_file(path);
  return input_face_from_occt(select_face(shape, path + ": the file", face_number, how_to_choose),
                              face_source_name(path, face_number));
}

InputFace input_face_from_occt(const TopoDS_Face& face, const std::string& source) {
  InputFace input;
  input.source = source;
  input.occt = face;
  try {
    input.planar = planar_face_from_occt(face);
    input.grid = make_grid_face(input.planar.polygon);
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
  return input;
}

}  // namespace autoblock
