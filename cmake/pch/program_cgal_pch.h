// program_pch.h and the mesh readers and samplers that bring CGAL in, precompiled once per build
// directory for PCCD's own programs that link CGAL: the pccd tool, most benchmarks, the accuracy
// programs and the command-line tests' reference programs. A header precompiled without CGAL's
// -frounding-math cannot serve them, hence a second one. Only a build-time saving.
#pragma once

#include "program_pch.h"

#include <PCCD/IO/read_points.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/sample_triangle_mesh.h>
