"""
pccd -- collision detection and intersection of point clouds
=============================================================

Python interface of PCCD, a C++20 library that answers whether two point clouds touch, and
where, without reconstructing a mesh. Each cloud defines a smooth implicit surface (weighted
least squares over geodesic neighbourhoods); two posed surfaces are intersected stochastically.

Each cloud is preprocessed once into an `Object` (from an (N, 3) array or an Open3D point cloud);
queries then pose objects by rigid transforms (3x4 ``[R | t]`` or 4x4 homogeneous numpy arrays)
and answer in microseconds to milliseconds.

Functions and classes
---------------------
read_points, write_points
    Point files (PLY, OFF, XYZ/PWN) to and from numpy arrays.
Object
    A preprocessed point cloud; ``Object.save`` / ``Object.load`` keep it in a file.
LeanObject
    The lean object for large scans (from about 10^6 points): the Euclidean kernel, about a fifth
    of an Object's memory; every query but World takes it, alone or beside an Object;
    ``LeanObject.save`` / ``LeanObject.load`` keep it in a file.
load
    An object file of either kind (``Object.save``, ``LeanObject.save``, ``pccd prepare``) as the
    kind it holds.
do_intersect
    Whether two posed objects intersect (stops at the first point found).
intersection_points
    Points along the intersection curves.
do_intersect_many, intersection_points_many
    Many pairs in one call, on several threads (the GIL is released); bit for bit the
    single queries seeded by `pair_seed`.
Result
    The answer: ``intersects``, ``status``, ``points`` (an (M, 3) array), ``counters``,
    ``query_us``.
distance, within_distance, contacts
    How far apart two posed objects are (with witness points, normals and, on request,
    penetration depths), whether they come closer than a margin, and their contact regions.
distance_many
    distance for many pairs in one call, on several threads (seeded by `pair_seed`).
clearance
    An object moved along a path of poses through a scene: the clearance at every pose against
    a safety margin, the first pose below it and the minimum (on several threads).
DistanceResult, ClearanceResult, ContactResult, Contact, ClearanceProfile
    Their answers, with the attributes named as the fields of PCCD's C++ results.
time_of_contact, time_of_contact_many
    Continuous collision: when two objects moving rigidly (linear or screw motions between a start
    and an end pose) first come into contact; many pairs in one call, on several threads.
ContactTimeResult
    Its answer: ``status``, ``t``, ``t_low``, ``t_high``, ``point``, ``normal``, ``counters``.
World, WorldHandle
    A collision world: many posed instances of shared objects, all intersecting pairs at once
    (broad phase, parallel narrow phase, cache), filters, one-object, distance and box queries;
    ``world_pair_key`` and ``pair_seed`` give the seed of each pair.
orthonormalize
    The nearest rigid pose to a matrix whose rotation part is not quite one, and how far it
    moved (queries refuse R with R^T R - I beyond 1e-5; 6 printed decimals always pass).

Errors
------
Bad arrays, poses and options raise ValueError, unusable files OSError, both with PCCD's
message naming the problem.

Examples
--------
>>> import numpy as np, pccd
>>> points, _ = pccd.read_points("bunny00.off")
>>> bunny = pccd.Object(points)
>>> turn = np.array([[0., -1., 0., 0.05], [1., 0., 0., 0.], [0., 0., 1., 0.]])
>>> pccd.do_intersect(bunny, None, bunny, turn).intersects
True

The manual: doc/manual/python.md in PCCD's sources (the proximity queries:
doc/manual/proximity-cli-python.md; continuous collision: doc/manual/continuous.md).
"""

from ._pccd import (
    ClearanceProfile,
    ClearanceResult,
    Contact,
    ContactResult,
    ContactTimeResult,
    DistanceResult,
    LeanObject,
    Object,
    Result,
    World,
    WorldHandle,
    __version__,
    clearance,
    contacts,
    distance,
    distance_many,
    do_intersect,
    do_intersect_many,
    intersection_points,
    intersection_points_many,
    load,
    orthonormalize,
    pair_seed,
    read_points,
    time_of_contact,
    time_of_contact_many,
    within_distance,
    world_pair_key,
    write_points,
)

__all__ = [
    "__version__",
    "Object",
    "LeanObject",
    "load",
    "Result",
    "do_intersect",
    "do_intersect_many",
    "intersection_points",
    "intersection_points_many",
    "orthonormalize",
    "pair_seed",
    "read_points",
    "write_points",
    "distance",
    "within_distance",
    "contacts",
    "distance_many",
    "clearance",
    "DistanceResult",
    "ClearanceResult",
    "ClearanceProfile",
    "ContactResult",
    "Contact",
    "time_of_contact",
    "time_of_contact_many",
    "ContactTimeResult",
    "World",
    "WorldHandle",
    "world_pair_key",
]
