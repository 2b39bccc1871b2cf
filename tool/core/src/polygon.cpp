#include "hullcook/core/polygon.h"
