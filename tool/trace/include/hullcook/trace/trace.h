// Silhouette tracing from images (OpenCV).
#pragma once
