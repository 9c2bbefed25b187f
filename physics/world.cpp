// SPDX-License-Identifier: MIT
#include "physics/world.h"
