// The headers nearly every test program includes (Catch2, Eigen, the object and the queries),
// precompiled once per build directory, twice: for the test programs without CGAL and for those
// with CGAL's -frounding-math (pccd_add_test in test/CMakeLists.txt; off with -DPCCD_TEST_PCH=OFF).
// Only a build-time saving: each test still includes what it uses, and the header check of the build
// (pccd_header_check) compiles every public header on its own, without this file.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
