// PCCD/Euclidean_point_cloud_object.h -- the lean preprocessed object for scene-scale scans
// (Euclidean_point_cloud_object: the implicit surface with the Euclidean kernel, about a fifth of a
// Point_cloud_object per point) with its file format: the class
// (Euclidean_point_cloud_object_class.h) and its save() and load()
// (Euclidean_point_cloud_object_file.h). Implements doc/manual/surface.md, "The lean object: the
// Euclidean kernel for large scans".
#pragma once

#include <PCCD/Euclidean_point_cloud_object_class.h>
#include <PCCD/Euclidean_point_cloud_object_file.h>
