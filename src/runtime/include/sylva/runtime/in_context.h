// What InLeftContext(...), InRightContext(...), InNewLeftContext(...) and
// InNewRightContext(...) (LPFG manual 3.3) become in a compiled rule body.
//
// The translator turns `InLeftContext(F(x) G(y))` into an expression that
// asks the engine (through the body's RuleCall) whether F G follow in the
// left context and, if they do, copies their parameters into the variables
// x and y. Those are the model's own variables, declared beforehand with the
// module's parameter types. A variable of another type (even a convertible
// one, an int for a float parameter) is a compile error: the reference
// in_context_parameter takes cannot bind to it, and g++ reports "cannot bind
// non-const lvalue reference" at the line of the .l file with the test.
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/modules.h>

namespace sylva::rt {

inline bool in_context(abi::RuleCall* call, int part, const abi::ModuleId* pattern, int n,
                       const unsigned char** params) {
  return call->in_context && call->in_context(call->context, part, pattern, n, params);
}

// Copies parameter I of a matched module (parameter types T...) into the
// model's variable, which must have exactly that type.
template <std::size_t I, class... T>
inline void in_context_parameter(const unsigned char* params, typename ParamAt<I, T...>::type& variable) {
  variable = param<I, T...>(params);
}

}  // namespace sylva::rt
