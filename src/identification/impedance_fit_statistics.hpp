#pragma once
// The impedance fit's statistics at its optimum (impedance_identification.cpp): each
// estimate with its standard error and resolution, what the data do not determine,
// the lack-of-fit test against the stated scatter, and the fixed numbers that would
// move the estimates. Private to the identification module.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>

#include "impedance_fit_variables.hpp"
#include "least_squares.hpp"

namespace stockbridge::identification::impedance_fit {

/// How a law's numbers scale with the damper: "ei_min and ei_max times s^3, chi0 times s^-2".
std::string scaling_words(const cable::SectionLawDescriptor& law);

/// Parameter i outside the null space and resolved within kUndeterminedResolution.
bool determined_on_its_own(const std::vector<ParameterEstimate>& parameters, const least_squares::Statistics& s,
                           std::size_t i);

/// The first parameter not determined on its own whose estimate is correlated with
/// parameter i's beyond kTiedCorrelation; -1 if none.
int tied_partner(const std::vector<ParameterEstimate>& parameters, const least_squares::Statistics& s, std::size_t i);

/// Each variable's estimate (value, standard error, resolution, sensitivity), in the variables' order.
std::vector<ParameterEstimate> estimates(const FitVariables& variables, const Eigen::VectorXd& x,
                                         const least_squares::Statistics& s);

/// Each type's ei + sum c, a combination the data determine even where nothing slips
/// (none under a law of numbers, such as Bouc-Wen's, whose stick stiffness ei_max is a parameter).
std::vector<ParameterEstimate> stick_stiffnesses(const FitVariables& variables, const Eigen::VectorXd& x,
                                                 const least_squares::Statistics& s);

/// One sentence per null-space direction and per poorly resolved parameter, and
/// one where the fitted model never slips.
std::vector<std::string> determination_notes(const std::vector<ParameterEstimate>& parameters,
                                             const least_squares::Statistics& s,
                                             const std::vector<ParameterEstimate>& stick,
                                             const std::vector<damper::ImpedancePoint>& fitted);

/// The lack-of-fit test of the misfit S at the optimum against the stated `scatter`
/// of Z (m real residuals; the statistics' rank the parameters determined).
LackOfFit lack_of_fit(const least_squares::Statistics& s, double sum_of_squares, double rms, double scatter, bool assumed,
                      int residuals);

/// The change of parameter i's value (in its unit) for a change dx of its variable at x.
double value_change(const FitVariables& variables, const Eigen::VectorXd& x, int i, double dx);

/// Marks each parameter (confounded_by, confounded_shift) that a suspect explaining
/// at least explaining_share of the misfit, moved to its suggested value, would move
/// by more than its standard error (the suspect moving it most, in standard errors),
/// and says so: one note per such suspect.
std::vector<std::string> confounding_notes(const FitVariables& variables, const Eigen::VectorXd& x,
                                           const least_squares::Statistics& s,
                                           const std::vector<FixedNumberSuspect>& suspects,
                                           const std::vector<least_squares::ExtraVariable>& steps,
                                           std::vector<ParameterEstimate>& parameters);

}  // namespace stockbridge::identification::impedance_fit
