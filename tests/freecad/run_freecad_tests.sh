#!/usr/bin/env bash
# Runs AutoBlock's FreeCAD tests in a throw-away FreeCAD user folder (HOME and FREECAD_USER_HOME point to
# a temporary folder whose Mod/AutoBlock links to this checkout), so the user's own FreeCAD set-up is
# neither used nor touched.
#
#   run_freecad_tests.sh app NATIVE_DIR [CLI]                  freecadcmd -t TestAutoBlockApp
#   run_freecad_tests.sh gui NATIVE_DIR [CLI] [SCREENSHOT_DIR] xvfb-run freecad -t TestAutoBlockGui
#
# NATIVE_DIR: the folder of the built autoblock_native module; CLI: the autoblock tool (cross-checks).
# Passes only when the tests ran (at least one) and all passed: FreeCAD's -t exits 1 on failure, and an
# import error would otherwise run zero tests.
set -uo pipefail
kind=${1:?app or gui}
native=${2:?native module folder}
cli=${3:-}
shots=${4:-}
root=$(cd "$(dirname "$0")/../.." && pwd)

home=$(mktemp -d "${TMPDIR:-/tmp}/autoblock-freecad-XXXXXX")
trap 'rm -rf "$home"' EXIT
mkdir -p "$home/Mod" "$home/tmp"
ln -s "$root" "$home/Mod/AutoBlock"
export HOME="$home" FREECAD_USER_HOME="$home" AUTOBLOCK_NATIVE_DIR="$native" AUTOBLOCK_CLI="$cli" \
  AUTOBLOCK_TEST_TMP="$home/tmp" QTWEBENGINE_DISABLE_SANDBOX=1
log="$home/test.log"

case "$kind" in
  app)
    freecadcmd -t TestAutoBlockApp >"$log" 2>&1
    status=$?
    ;;
  gui)
    [ -n "$shots" ] && mkdir -p "$shots" && export AUTOBLOCK_SCREENSHOT_DIR="$shots"
    xvfb-run -a -s "-screen 0 1600x1000x24" freecad -t TestAutoBlockGui >"$log" 2>&1
    status=$?
    ;;
  *)
    echo "usage: $0 app|gui NATIVE_DIR [CLI] [SCREENSHOT_DIR]" >&2
    exit 2
    ;;
esac

# FreeCAD's progress output ("Recompute...") has no newlines; keep the log readable.
sed -e 's/\r//g' "$log"
if [ "$status" -ne 0 ]; then
  echo "run_freecad_tests: FreeCAD exited with status $status" >&2
  exit 1
fi
if ! grep -Eq '^Ran [1-9][0-9]* tests? in' "$log" || ! grep -Eq '^OK( |$)' "$log"; then
  echo "run_freecad_tests: no passing test run found in the output" >&2
  exit 1
fi
if [ "$kind" = gui ] && [ -n "$shots" ]; then
  for name in autoblock step-through train unsupported-face; do
    if [ ! -s "$shots/$name.png" ]; then
      echo "run_freecad_tests: screenshot $shots/$name.png is missing" >&2
      exit 1
    fi
  done
fi
exit 0
