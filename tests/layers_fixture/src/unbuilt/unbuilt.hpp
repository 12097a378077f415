// Not built, so not checked.
#pragma once

#include "top/top.hpp"
