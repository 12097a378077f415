// The violation: low links nothing, so it may not include high/.
#pragma once

#include "high/high.hpp"
#include "low/low_part.hpp"
