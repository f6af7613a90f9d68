// The central-difference stepper of the explicit solvers (frames: analysis/explicit_analysis,
// 3D continuum: solid/solid_explicit): Boost.Odeint's velocity Verlet on Eigen vectors.
// vector_space_algebra applies its operations to whole vectors (t1 = a1 t2 + a2 t3 + a3 t4),
// which Eigen evaluates in one expression.
#pragma once

#include <Eigen/Core>

#include <boost/numeric/odeint/algebra/default_operations.hpp>
#include <boost/numeric/odeint/algebra/vector_space_algebra.hpp>
#include <boost/numeric/odeint/stepper/velocity_verlet.hpp>

namespace brb::analysis {

using EigenVelocityVerlet = boost::numeric::odeint::velocity_verlet<
    Eigen::VectorXd, Eigen::VectorXd, double, Eigen::VectorXd, double, double,
    boost::numeric::odeint::vector_space_algebra, boost::numeric::odeint::default_operations>;

} // namespace brb::analysis
