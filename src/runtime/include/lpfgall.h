// lpfgall.h — what an L+C model sees of the system.
//
// Models written for lpfg include this file first; it provides the predefined
// modules, the vector types V2f V2d V3f V3d, and the predefined functions.
// Including it also marks where the translation of L+C into C++ begins.
#pragma once

#include <sylva/runtime/vectors.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/modules.h>
#include <sylva/runtime/functions.h>
#include <sylva/runtime/in_context.h>
