// Its own stage: allowed.
#pragma once
