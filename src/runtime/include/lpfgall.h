// lpfgall.h — what an L+C model sees of the system.
//
// Models written for lpfg include this file first. It gives them what
// lpfg's own lpfgall.h gives (LPFG manual chapters 5 to 9), so that a model
// that compiles with lpfg compiles here, including what models use without
// knowing where it comes from:
//   - the standard headers lpfg's pulls in: <memory.h> <stdlib.h> <stdio.h>
//     <cmath> <string> <iostream> (so printf, sqrt, M_PI, std::string,
//     std::cout, malloc and memcpy need no #include of their own);
//   - its macros: the include guards __LPFGALL_H__ __LINTRFC_H__
//     __LPARAMS_H__ __LSYS_H__ __STDMODS_H__, M_PI, DECLSPEC,
//     StartBranchIdent and EndBranchIdent;
//   - its types (V2f ... V3td, SurfaceObj, MouseStatus, CameraPosition, ...),
//     the predefined modules and the predefined functions.
// Including it also marks where the translation of L+C into C++ begins.
#pragma once

#ifndef __LPFGALL_H__
#define __LPFGALL_H__
#define __LINTRFC_H__
#define __LPARAMS_H__
#define __LSYS_H__
#define __STDMODS_H__

#include <memory.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmath>
#include <iostream>
#include <string>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

// How lpfg exports a model's entry points; models that declare functions of
// their own with it still compile.
#define DECLSPEC extern "C"
// The names of the branching modules.
#define StartBranchIdent "SB"
#define EndBranchIdent "EB"

// lpfg's limits on identifiers, parameters and modules, and its kinds of group.
enum {
  __lc_eMaxIdentifierLength = 32,
  __lc_eMaxParams = 64,
  __lc_eMaxFormalModules = 32,
  __lc_eFirstModuleId = 2
};
enum __lc_GroupType { __lc_gtUnspecified, __lc_gtLsystem, __lc_gtGillespie };

#include <sylva/runtime/vectors.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/modules.h>
#include <sylva/runtime/functions.h>
#include <sylva/runtime/input_functions.h>
#include <sylva/runtime/interaction.h>
#include <sylva/runtime/in_context.h>
#include <sylva/runtime/continuous.h>

#endif  // __LPFGALL_H__
