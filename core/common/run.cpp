#include "core/common/run.h"

namespace metrofit {

const char* toString(Termination t) {
  switch (t) {
    case Termination::Converged:
      return "converged";
    case Termination::BudgetExhausted:
      return "budget exhausted";
    case Termination::MaxIterations:
      return "iteration limit";
    case Termination::Cancelled:
      return "cancelled";
    case Termination::Failed:
      return "failed";
  }
  return "unknown";
}

}  // namespace metrofit
