// PCCD/PCCD.h -- the whole core of PCCD in one include: every public header except those that need
// CGAL (PCCD/IO/read_*.h and write_*.h, which read and write files through CGAL, and PCCD/Exact/,
// the exact reference). A program that includes only this header and links PCCD::PCCD (Eigen,
// Boost, nanoflann, optionally TBB) can sample, preprocess, query and animate; see
// doc/design.md for the stages and doc/manual.md for their use. test/umbrella/
// checks that it stays complete and free of CGAL.
#pragma once

// Foundation: kernels, points, the cloud and its kd-tree, poses, errors, randomness
#include <PCCD/Eigen_kernel.h>
#include <PCCD/Error.h>
#include <PCCD/Identity_point_map.h>
#include <PCCD/Kd_tree.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Point_traits.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/version.h>

// Concepts
#include <PCCD/concepts/CollisionObject.h>
#include <PCCD/concepts/LeafIntersector.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>
#include <PCCD/concepts/PairObserver.h>
#include <PCCD/concepts/PathSource.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/concepts/RigidMotion.h>
#include <PCCD/concepts/ProximityGraph.h>
#include <PCCD/concepts/ReadablePointMap.h>
#include <PCCD/concepts/SurfaceDistance.h>
#include <PCCD/concepts/SurfaceWeight.h>
#include <PCCD/concepts/TreeWalk.h>

// Plain data of files (reading and writing them needs CGAL: PCCD/IO/read_*.h, write_*.h)
#include <PCCD/IO/Format.h>
#include <PCCD/IO/Point_data.h>
#include <PCCD/IO/Triangle_mesh_data.h>

// Clouds from triangle meshes, and the unit-cube normalization
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

// Proximity graphs, the sampling radius, geodesic distances
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Geodesic/Paths_on_the_fly.h>
#include <PCCD/Geodesic/Stored_paths.h>
#include <PCCD/Geodesic/geodesic_io.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Proximity_graph/graph_options.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/prune_long_edges.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/sampling_radius.h>
#include <PCCD/sampling_radius_options.h>

// The implicit surface and the preprocessed object
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Euclidean_point_cloud_object_class.h>
#include <PCCD/Euclidean_point_cloud_object_file.h>
#include <PCCD/Point_cloud_object_class.h>
#include <PCCD/Point_cloud_object_file.h>
#include <PCCD/Point_cloud_object_preprocessing.h>
#include <PCCD/Point_cloud_object_options.h>
#include <PCCD/Surface/Euclidean_distance.h>
#include <PCCD/Surface/Gaussian_weight.h>
#include <PCCD/Surface/Geodesic_distance.h>
#include <PCCD/Surface/Surface_fit.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/Surface/bandwidth.h>
#include <PCCD/Surface/estimate_normals.h>
#include <PCCD/Surface/local_spacing.h>
#include <PCCD/Surface/orient_normals.h>
#include <PCCD/Surface/outliers.h>
#include <PCCD/Surface/surface_options.h>
#include <PCCD/Surface/surface_domain.h>
#include <PCCD/make_point_cloud_object.h>
#include <PCCD/object_file_info.h>
#include <PCCD/sharp_feature_options.h>

// Hierarchy and intersection queries
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy_options.h>
#include <PCCD/Hierarchy/Reach_rule.h>
#include <PCCD/Hierarchy/Sphere_covering.h>
#include <PCCD/Hierarchy/node_pair_tests.h>
#include <PCCD/Hierarchy/overlapping_leaves.h>
#include <PCCD/Hierarchy/point_queries.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Intersection/Interpolation_search.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/Posed_object.h>
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Intersection/Randomized_sampling.h>
#include <PCCD/Intersection/Ray_hit.h>
#include <PCCD/Intersection/Ray_options.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Intersection/ray_intersection.h>
#include <PCCD/Intersection/refinement.h>
#include <PCCD/Proximity/Clearance_options.h>
#include <PCCD/Proximity/Clearance_profile.h>
#include <PCCD/Proximity/Distance_options.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Proximity/clearance.h>
#include <PCCD/Proximity/contacts.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Proximity/distance_many.h>

// Continuous collision: rigid motions and the first contact time
#include <PCCD/Continuous/Contact_time_names.h>
#include <PCCD/Continuous/Contact_time_options.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Continuous/time_of_contact.h>

// Collision worlds: many posed objects, a broad phase and the narrow-phase queries
#include <PCCD/World/Collision_world.h>
#include <PCCD/World/Dynamic_AABB_tree.h>
#include <PCCD/World/World_handle.h>
#include <PCCD/World/World_options.h>
#include <PCCD/World/World_results.h>
#include <PCCD/World/world_box.h>

// Kinetic AABB trees
#include <PCCD/Kinetic/Cubic.h>
#include <PCCD/Kinetic/Deformation.h>
#include <PCCD/Kinetic/Deforming_motion.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Kinetic/Event_queue.h>
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Kinetic_primitives.h>
#include <PCCD/Kinetic/Kinetic_ray.h>
#include <PCCD/Kinetic/Kinetic_statistics.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Kinetic/Piecewise_linear_flightplan.h>
#include <PCCD/Kinetic/Polynomial_flightplan.h>
#include <PCCD/Kinetic/Refit_AABB_tree.h>
#include <PCCD/Kinetic/boxes_overlap.h>
#include <PCCD/Kinetic/flightplan_speed.h>
#include <PCCD/Kinetic/intersect_ray_triangle.h>
#include <PCCD/Kinetic/next_crossing.h>
