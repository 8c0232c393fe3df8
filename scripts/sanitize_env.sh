# Sourced by `scripts/test --sanitize`: runtime options for the AddressSanitizer + UBSan build.
# Source it yourself to run single sanitized tests or nodes by hand (after scripts/test --sanitize
# built .build/ws_sanitize).
_symseg_root="$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)"
# Leaks are errors, except the ones listed (with the reason) in the suppression file.
export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1:symbolize=1"
export LSAN_OPTIONS="suppressions=$_symseg_root/test/sanitize/lsan.supp:print_suppressions=0"
# Undefined behaviour stops the process, so a test cannot pass past it.
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# Our sanitized executables link the ASan runtime first; the stock nodelet manager does not, and
# loading the sanitized nodelet library into it needs the runtime preloaded. launch/
# segmentation.launch puts this in front of the manager's command line.
_symseg_asan="$(gcc -print-file-name=libasan.so)"
export SYMSEG_MANAGER_PREFIX="env LD_PRELOAD=$(readlink -f "$_symseg_asan")"
unset _symseg_root _symseg_asan
