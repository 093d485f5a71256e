// What a Virtual Laboratory environmental program sees of a pass, and what
// the modeling program keeps of its answers, when the two talk through the
// Virtual Laboratory's communication library (libs/comm). The built-in
// programs (honda81, clover, ...) compute in process; this layer gives them
// the values the real program would have read, and writes back what lpfg or
// cpfg would have accepted:
//
//  - A module's parameters travel as text: lpfg prints them with "%f"
//    (six decimals), cpfg with "%g" (six significant digits); the program
//    reads them back as floats.
//  - Each turtle field is printed with the .e file's format; the program skips
//    the text before the format's first conversion and reads up to three
//    numbers with sscanf("%f %f %f"). Values it cannot read keep what the
//    previous query had.
//  - Answers travel as "%g". A program answers n parameters (n = the highest
//    one it sets, plus one). lpfg takes an answer to E1 only when n is 1, to
//    E2 only when n is 2, to EA20 when n is at most 20, and then writes all n
//    values, 0 for those the program left unset; any other answer is dropped
//    with lpfg's message. cpfg writes the values the program set, as far as
//    the module has parameters, and warns about the rest.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "env/comm_spec.h"
#include "env/field.h"

namespace sylva::env {

// The modeling program whose side of the communication library is imitated.
enum class ModelingProgram { lpfg, cpfg };

// `program` wrapped so that it sees the pass as the real program would.
// `warn` receives lpfg's and cpfg's messages about dropped answers (one line
// per pass, with a count).
std::unique_ptr<Field> through_comm_library(std::unique_ptr<Field> program, const CommSpec& spec,
                                            ModelingProgram master, std::function<void(const std::string&)> warn);

}  // namespace sylva::env
