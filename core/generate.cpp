// SPDX-License-Identifier: MIT
#include "core/generate.h"
