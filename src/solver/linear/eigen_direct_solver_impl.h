// Definition of make_eigen_factorization (included by the four Eigen solver files only).
#pragma once

#include <iostream>  // Eigen/MetisSupport uses std::cerr without including it
#include <Eigen/MetisSupport>
#include <Eigen/OrderingMethods>

#include "solver/linear/eigen_direct_solver.h"

namespace sinew {

template <template <class> class Solver>
std::unique_ptr<EigenFactorization> make_eigen_factorization(const std::string& ordering) {
  if (ordering == "Natural") return std::make_unique<EigenFactorizationOf<Solver<Eigen::NaturalOrdering<int>>>>();
  if (ordering == "AMD") return std::make_unique<EigenFactorizationOf<Solver<Eigen::AMDOrdering<int>>>>();
  if (ordering == "COLAMD") return std::make_unique<EigenFactorizationOf<Solver<Eigen::COLAMDOrdering<int>>>>();
  if (ordering == "Metis") return std::make_unique<EigenFactorizationOf<Solver<Eigen::MetisOrdering<int>>>>();
  return nullptr;
}

}  // namespace sinew
