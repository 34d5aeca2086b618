#pragma once
// The parts of `import linkwright` each file binds (module.cpp calls them in turn).

#include "python/src/initialised.h"
#include "python/src/linkage.h"

#include <pybind11/pybind11.h>

// A Linkage made by __new__ alone is refused, not used (initialised.h).
LINKWRIGHT_PYTHON_REFUSE_UNINITIALISED(linkwright::python::Linkage)

namespace linkwright::python {

/// linkwright.PathSearch and PATH_STARTS_PER_BLOCK (synthesis.cpp).
void bindSynthesis(pybind11::module_& module);

/// synthesize_crank_rocker, synthesize_slider_crank, synthesize_shaper, synthesize_function
/// (problems.cpp).
void bindProblems(pybind11::module_& module);

/// Linkage.tolerance_study (tolerance.cpp).
void bindTolerance(pybind11::class_<Linkage>& linkage);

/// linkwright.arm (arm.cpp); its notes are `warning`s (linkwright.SweepWarning).
void bindArm(pybind11::module_& module, pybind11::handle warning);

/// linkwright.accuracy (accuracy.cpp).
void bindAccuracy(pybind11::module_& module);

/// linkwright.Atlas (atlas.cpp).
void bindAtlas(pybind11::module_& module);

/// Linkage.instant_centres (centres.cpp).
void bindCentres(pybind11::class_<Linkage>& linkage);

/// Linkage.machine (machine.cpp).
void bindMachine(pybind11::class_<Linkage>& linkage);

/// Linkage.polygons and Linkage.inversions (classroom.cpp).
void bindClassroom(pybind11::class_<Linkage>& linkage);

/// Linkage.cognates (cognates.cpp).
void bindCognates(pybind11::class_<Linkage>& linkage);

/// Linkage.balance (balance.cpp).
void bindBalance(pybind11::class_<Linkage>& linkage);

/// Linkage.dxf (dxf.cpp).
void bindDxf(pybind11::class_<Linkage>& linkage);

/// Linkage.extremes (extremes.cpp).
void bindExtremes(pybind11::class_<Linkage>& linkage);

}  // namespace linkwright::python
