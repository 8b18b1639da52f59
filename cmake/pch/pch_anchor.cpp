// The translation unit that builds a precompiled header of PCCD's programs (cmake/pch/; cmake/PCCDInternalTargets.cmake).
