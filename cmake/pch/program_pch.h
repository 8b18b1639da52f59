// The headers most of PCCD's own programs include (the standard library, Eigen, the object, the
// intersection query and the poses), precompiled once per build directory and reused by the
// benchmarks that do not link CGAL (pccd_add_program in cmake/PCCDInternalTargets.cmake;
// off with -DPCCD_PROGRAM_PCH=OFF). Only a build-time saving: every program still includes what it
// uses, and the header check of the test build compiles every public header on its own.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
