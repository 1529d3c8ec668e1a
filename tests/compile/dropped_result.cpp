// Compiled by tests/compile/nodiscard_test.sh, never linked: a Status and a
// Result dropped without a (void) cast must not compile (-Werror=unused-result,
// core/result.h's [[nodiscard]]); with SMPL_CAST_TO_VOID they are dropped on
// purpose and it compiles.
#include "core/result.h"

smpl::Status check() { return smpl::makeError("x"); }
smpl::Result<int> parse() { return 1; }

void caller() {
#ifdef SMPL_CAST_TO_VOID
  (void)check();
  (void)parse();
#else
  check();
  parse();
#endif
}
