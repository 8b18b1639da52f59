// PCCD/Point_cloud_object.h -- the whole preprocessed state of one point cloud (points and kd-tree,
// proximity graph, sampling radius, CPSP map, oriented normals, the kernel bandwidth and domain of
// the implicit surface, the point cloud hierarchy), built in one call, saved to and loaded from one
// binary file. Implements doc/manual/surface.md, "One call: Point_cloud_object" (and its save and
// load). The object is three headers beside each other: the class (Point_cloud_object_class.h),
// its preprocessing pipeline (Point_cloud_object_preprocessing.h) and its file format
// (Point_cloud_object_file.h); include this one.
#pragma once

#include <PCCD/Point_cloud_object_class.h>
#include <PCCD/Point_cloud_object_file.h>
#include <PCCD/Point_cloud_object_preprocessing.h>
