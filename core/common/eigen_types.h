#pragma once
// One place for the Eigen aliases used across core (STYLE 7). Pass
// Eigen::Ref<const ...> across APIs; complex spectra are Eigen::VectorXcd.

#include <Eigen/Core>
#include <complex>

namespace mozzi::core {

using Complex = std::complex<double>;

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
using ComplexVector = Eigen::VectorXcd;
using ComplexMatrix = Eigen::MatrixXcd;
using Vector2 = Eigen::Vector2d;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

using VectorRef = Eigen::Ref<const Eigen::VectorXd>;
using MatrixRef = Eigen::Ref<const Eigen::MatrixXd>;
using ComplexVectorRef = Eigen::Ref<const Eigen::VectorXcd>;
using ComplexMatrixRef = Eigen::Ref<const Eigen::MatrixXcd>;

}  // namespace mozzi::core
