# Source this file (`source scripts/env.sh`) to use the built workspace:
# `rosrun symmetry_segmentation <tool>` then works. Debian's python3 goes first on PATH, since
# catkin's Python modules live there and not in a pyenv Python.
_symseg_root="$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)"
export PATH="/usr/bin:/bin:$PATH"
_symseg_ws="${SYMSEG_WORKSPACE:-$_symseg_root/.build/ws}"
if [ -f "$_symseg_ws/devel/setup.bash" ]; then
  # shellcheck disable=SC1091
  source "$_symseg_ws/devel/setup.bash"
else
  echo "symmetry_segmentation: no build at $_symseg_ws; run scripts/demo or scripts/test first" >&2
fi
unset _symseg_ws _symseg_root
