// Parameters' table types (abi::ParamType) as a model describes a float, a
// double, an int, an unsigned char, a bool and a label's text: the text
// writer's and reader's tests build their blocks from them.
#pragma once

#include "sylva/abi.h"

namespace sylva::test {

inline const abi::ParamType kFloat{abi::ParamKind::kFloat, 4};
inline const abi::ParamType kDouble{abi::ParamKind::kDouble, 8};
inline const abi::ParamType kInt{abi::ParamKind::kSigned, 4};
inline const abi::ParamType kByte{abi::ParamKind::kUnsigned, 1};
inline const abi::ParamType kBool{abi::ParamKind::kBool, 1};
inline const abi::ParamType kText{abi::ParamKind::kText, sizeof(const char*)};

}  // namespace sylva::test
