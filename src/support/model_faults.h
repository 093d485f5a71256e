// A fault inside a model's code (its productions, rules, control statements
// and functions are C++ the engine calls) reported as the model's error, at
// the rule it happened in and the step, rather than ending the run unnamed.
//
// Every call into the model goes through call_model(), which notes where it
// is (a few stores, so it costs nothing next to a rule's body) and turns an
// exception of any type into a ModelError there. A fatal signal raised in
// model code (SIGSEGV, SIGFPE, SIGBUS, SIGILL, SIGABRT, a stack overflow
// included) is reported from that note by the handler install_handler() sets:
// it prints the message, removes the run's temporary files
// (interruption::clean_up_now) and ends the process with the signal. A fatal
// signal outside model code is left to whatever handled it before.
#pragma once

#include <exception>
#include <new>
#include <utility>

#include "support/diagnostic.h"

namespace sylva::model_faults {

// Where the engine is in the model's code.
struct CallSite {
  const char* what = nullptr;  // "production", "StartEach" ...; null: not in model code
  const char* file = nullptr;  // may be null
  int line = 0;                // 0: not known
  // The derivation step (StepNo()), read where a fault is reported, so one
  // site serves a rule at every step; null: not known.
  const int* step = nullptr;

  int step_now() const { return step ? *step : 0; }
};

// The calling thread's site, or null outside model code; a synchronous signal
// arrives on the thread that raised it. A pointer, so that entering and
// leaving model code, once per rule applied, is one store each.
inline thread_local const CallSite* current_site = nullptr;

// Installs the fatal-signal handler (once per process) and an alternate
// signal stack for the calling thread, so a stack overflow is reported too.
void install_handler();

// Blocks on the calling thread every signal but the faults the handler
// reports: a helper thread that lives on between passes leaves the signals
// sent to the process (an interruption, a child's end) to the threads that
// were there before it.
void block_all_but_faults();

// The ModelError for the exception being handled, thrown by the model at `site`.
[[noreturn]] void rethrow_as_model_error(const CallSite& site);

// Calls `model_code` as the model's code at `site`, which lives until it returns.
template <class ModelCode>
decltype(auto) call_model(const CallSite& site, ModelCode&& model_code) {
  struct Noted {
    const CallSite* saved = current_site;
    explicit Noted(const CallSite& s) { current_site = &s; }
    ~Noted() { current_site = saved; }
  } noted(site);
  try {
    return std::forward<ModelCode>(model_code)();
  } catch (const ModelError&) {
    throw;  // the engine's own, from a callback the model made
  } catch (const std::bad_alloc&) {
    throw;  // the string outgrew memory: the engine's limits say so
  } catch (...) {
    rethrow_as_model_error(site);
  }
}

}  // namespace sylva::model_faults
