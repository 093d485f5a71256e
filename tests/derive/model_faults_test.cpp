// A fault in the model's code, reported at the rule or control statement it
// happened in and the step: exceptions of any type as a ModelError, fatal
// signals by the handler, which also removes the run's temporary files.
#include "support/model_faults.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "derive/derivation.h"
#include "hand_built_model.h"
#include "support/interruption.h"
#include "test_support.h"

namespace sylva::test {
namespace {

constexpr abi::ModuleId kA = rt::mid::PredefinedCount;

// A(x) -> A(x+1) until x reaches 2, where the body does what `fault` says.
// The rule is the model's first: hand-built:1.
using Fault = void (*)();

Fault fault_in_body = nullptr;

void grow(abi::RuleCall* call, const unsigned char* const* p) {
  if (param(p, 0) >= 2) fault_in_body();
  produce(call, {{kA, {param(p, 0) + 1}}});
}

class ModelFaults : public ::testing::Test {
 protected:
  ModelFaults() {
    model_.module("A", 1);
    model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kA, {1}}}); });
    model_.set_derivation_length([] { return 5; });
    model_.production({.strict = {kA}}, grow);
  }
  // Runs the model with `fault` in its production (and `statement` as its
  // StartEach when given).
  void run(Fault fault, void (*start_each)() = nullptr) {
    fault_in_body = fault;
    descriptor_ = model_.descriptor();
    descriptor_.start_each = start_each;
    derive::Derivation derivation(descriptor_, [](const std::string&) {});
    derivation.run();
  }

  HandBuiltModel model_;
  abi::ModelDescriptor descriptor_{};
};

// The message a ModelError thrown by `run` carries.
template <class Run>
std::string error_of(Run&& run) {
  try {
    run();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(ModelFaults, AThrownIntIsTheProductionsErrorAtItsStep) {
  // A(1) -> A(2) in step 1; the body throws on A(2), in step 2.
  EXPECT_EQ(error_of([&] { run([] { throw 42; }); }),
            "hand-built:1: error: model threw an exception in production (int) (step 2)");
}

TEST_F(ModelFaults, AStandardExceptionSaysWhatItIs) {
  EXPECT_EQ(error_of([&] { run([] { throw std::out_of_range("index 7"); }); }),
            "hand-built:1: error: model threw an exception in production (std::out_of_range: index 7) (step 2)");
}

TEST_F(ModelFaults, AControlStatementsExceptionNamesTheStatement) {
  EXPECT_EQ(error_of([&] { run(nullptr, [] { throw "text"; }); }),
            "hand-built: error: model threw an exception in StartEach (char const*) (step 1)");
}

TEST_F(ModelFaults, TheEnginesOwnErrorsPassUnchanged) {
  const std::string error = error_of([&] { run([] { throw ModelError(SourceLocation{"m.l", 3, 4}, "as it was"); }); });
  EXPECT_EQ(error, "m.l:3:4: error: as it was");
  EXPECT_THROW(run([] { throw std::bad_alloc(); }), std::bad_alloc);
}

TEST_F(ModelFaults, NoSiteIsNotedOutsideModelCode) {
  run([] {
    ASSERT_NE(model_faults::current_site, nullptr);
    EXPECT_STREQ(model_faults::current_site->what, "production");
  });
  EXPECT_EQ(model_faults::current_site, nullptr);
  try {
    run([] { throw 1; });
  } catch (const ModelError&) {
  }
  EXPECT_EQ(model_faults::current_site, nullptr);
}

// ---- fatal signals (each in a child process: gtest's death tests)

volatile int zero = 0;  // the compiler must divide at run time

void divide_by_zero() { std::exit(7 / zero); }
void write_through_null() { *static_cast<volatile int*>(nullptr) = 1; }
int deeper_than_any_stack = 1 << 30;
int recurse(int depth) {
  volatile char frame[1024];
  frame[0] = static_cast<char>(depth);
  return depth < deeper_than_any_stack ? recurse(depth + 1) + frame[0] : 0;
}

using ModelFaultsDeathTest = ModelFaults;

TEST_F(ModelFaultsDeathTest, IntegerDivisionByZero) {
  EXPECT_EXIT(run(divide_by_zero), ::testing::KilledBySignal(SIGFPE),
              "^hand-built:1: error: model crashed in production \\(SIGFPE, integer division by zero\\) "
              "\\(step 2\\)\n$");
}

TEST_F(ModelFaultsDeathTest, NullPointer) {
  EXPECT_EXIT(run(write_through_null), ::testing::KilledBySignal(SIGSEGV),
              "hand-built:1: error: model crashed in production \\(SIGSEGV, null pointer\\) \\(step 2\\)");
}

TEST_F(ModelFaultsDeathTest, StackOverflow) {
  EXPECT_EXIT(run([] { std::exit(recurse(0)); }), ::testing::KilledBySignal(SIGSEGV),
              "hand-built:1: error: model crashed in production \\(SIGSEGV, stack overflow\\) \\(step 2\\)");
}

TEST_F(ModelFaultsDeathTest, AbortInAControlStatement) {
  EXPECT_EXIT(run(nullptr, [] { std::abort(); }), ::testing::KilledBySignal(SIGABRT),
              "hand-built: error: model crashed in StartEach \\(SIGABRT, aborted\\) \\(step 1\\)");
}

TEST_F(ModelFaultsDeathTest, TemporaryFilesAreRemoved) {
  const std::string dir = make_temp_dir("model-fault-temporary");
  const std::string partial = dir + "/out.txt.tmp1";
  EXPECT_EXIT(
      {
        std::ofstream(partial) << "half";
        const interruption::TemporaryFile registered(partial);
        run(divide_by_zero);
      },
      ::testing::KilledBySignal(SIGFPE), "model crashed");
  EXPECT_FALSE(std::filesystem::exists(partial));
}

TEST_F(ModelFaultsDeathTest, AFaultOutsideModelCodeIsNotTheModels) {
  // The handler is installed (a derivation was made) but the engine is not in the model.
  EXPECT_EXIT(
      {
        run([] {});
        std::fputs("outside\n", stderr);
        write_through_null();
      },
      ::testing::KilledBySignal(SIGSEGV), "^outside\n$");
}

}  // namespace
}  // namespace sylva::test
