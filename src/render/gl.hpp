// The one way render code includes GL: glad2's generated core 3.3 header (never GL/gl.h).
#pragma once

#include <glad/gl.h>
