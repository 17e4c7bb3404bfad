#pragma once
// GLPK's terminal output off for a scope: core never prints, and the CLI's stdout carries results
// only. The guard calls glp_term_out(GLP_OFF) when it is made and puts the previous setting back when
// it goes. GLPK keeps the setting in its environment, one per thread (Debian's libglpk is built
// reentrant with thread-local storage), so a guard silences the thread that made it. Include only
// in the .cpp files that call GLPK.
#include <glpk.h>

namespace metrofit {

class GlpkQuiet {
 public:
  GlpkQuiet() : previous_(glp_term_out(GLP_OFF)) {}
  ~GlpkQuiet() { glp_term_out(previous_); }
  GlpkQuiet(const GlpkQuiet&) = delete;
  GlpkQuiet& operator=(const GlpkQuiet&) = delete;

 private:
  int previous_;
};

}  // namespace metrofit
