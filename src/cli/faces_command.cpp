// autoblock faces FILE: the faces of a part, numbered as FreeCAD numbers them (Face1, Face2, ...),
// with their surface type, area, normal and whether AutoBlock takes them (for --face N).
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/commands.h"
#include "core/common/format.h"
#include "core/io/face_selection.h"
#include "core/io/shape_file.h"

namespace autoblock::cli {

void add_faces_command(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "faces", "List the faces of a .brep, .step or .stp file with their numbers (for --face N), surface, area and normal.");
  command->add_option("FILE", *file, "a .brep, .step or .stp file")->required();
  command->callback([file] {
    const std::vector<FaceSummary> faces = list_faces(read_shape_file(*file));
    int usable = 0;
    for (const FaceSummary& f : faces) usable += f.problem.empty() ? 1 : 0;
    std::cout << *file << ": " << counted(static_cast<long long>(faces.size()), "face") << "; AutoBlock can use "
              << usable << " (choose with --face N)\n";
    std::printf("%6s  %-16s  %14s  %-16s  %s\n", "face", "surface", "area", "normal", "AutoBlock");
    for (const FaceSummary& f : faces) {
      const std::string area = format_number(f.area, f.area * 1e-6);
      std::string normal = "-";
      if (f.planar) {
        constexpr double kDirectionTolerance = 1e-9;
        normal = "(" + format_number(f.normal[0], kDirectionTolerance) + ", " +
                 format_number(f.normal[1], kDirectionTolerance) + ", " +
                 format_number(f.normal[2], kDirectionTolerance) + ")";
      }
      // Why not, in its first clause: the rest of the check's message says what is supported.
      const std::string why = f.problem.substr(0, f.problem.find("; "));
      std::printf("%6d  %-16s  %14s  %-16s  %s\n", f.number, f.surface.c_str(), area.c_str(), normal.c_str(),
                  f.problem.empty() ? "yes" : ("no: " + why).c_str());
    }
  });
}

}  // namespace autoblock::cli
