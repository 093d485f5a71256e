#include "turtle/interpreter.h"
