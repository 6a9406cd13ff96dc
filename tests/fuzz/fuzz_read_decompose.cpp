// libFuzzer target: BREP text through everything a user's file goes through in `autoblock
// decompose --policy greedy --out`: reading (the hardened stream, in this process), the face checks,
// the greedy decomposition, the cuts on the OpenCASCADE face and the conformal merge.
//
// Every input must end in a decomposition or an InputError; a crash, a hang (libFuzzer -timeout),
// a leak or any other exception is a finding.
//
// AUTOBLOCK_FUZZ_RAW_READER=1 reads with OpenCASCADE's BRepTools::Read on a plain stream instead
// (what AutoBlock did before the hardening), to check that the fuzzer finds that reader's hangs.
#include <BRepTools.hxx>
#include <OSD.hxx>
#include <BRep_Builder.hxx>
#include <Standard_Failure.hxx>

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/baselines/greedy_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/env/occt_replay.h"
#include "core/io/input_face.h"
#include "core/io/face_selection.h"
#include "core/io/shape_file.h"
#include "core/mesh/conformal_merge.h"

namespace {

bool raw_reader = false;

autoblock::InputFace read_raw(const std::string& text) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  std::istringstream in(text);
  try {
    BRepTools::Read(shape, in, builder);
  } catch (const Standard_Failure&) {
    throw autoblock::InputError("unreadable");
  }
  return autoblock::input_face_from_occt(autoblock::select_face(shape, "fuzz", 0), "fuzz");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Read in this process: libFuzzer must see crashes and hangs itself, not a child's. Like the
  // reading child (isolated_call.h), with OpenCASCADE's signal handling: its reader catches an
  // access violation inside itself (OCC_CATCH_SIGNALS) and carries on.
  ::setenv("AUTOBLOCK_READ_TIMEOUT", "0", 1);
  OSD::SetSignal(OSD_SignalMode_Set, false);
  const char* raw = std::getenv("AUTOBLOCK_FUZZ_RAW_READER");
  raw_reader = raw && std::string(raw) == "1";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  using namespace autoblock;
  InputFace face;
  try {
    face = raw_reader ? read_raw(text) : input_face_from_brep_text(text, "fuzz");
  } catch (const InputError&) {
    return 0;
  }
  GreedyPolicy greedy;
  EpisodeOptions options;
  const Decomposition result = decompose_face(face.grid, greedy, options);
  if (result.cuts.size() <= 64) {  // OpenCASCADE's cuts cost milliseconds each
    try {
      conformal_merge(replay_cuts_occt(face.occt, face.grid, result.cuts, options));
    } catch (const InputError&) {
    }
  }
  return 0;
}
