#include "hullcook/trace/trace.h"
