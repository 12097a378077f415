// top links high, which passes low on: both allowed.
#pragma once

#include "high/high.hpp"
#include "low/low_part.hpp"
