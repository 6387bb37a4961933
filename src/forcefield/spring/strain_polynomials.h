// The polynomials of SOFA's PolynomialSprings and PolynomialRestShapeSprings
// force fields: polynomial p has degree[p] coefficients, taken in order from
// one flat list, P_p(s) = Σ_{k=1..deg} c_k s^k (no constant term). Evaluated
// with SOFA's running power and sums, so the same roundings.
#pragma once

#include <string>
#include <vector>

namespace sinew {

class StrainPolynomials {
 public:
  // Builds the table; an error message (empty when fine) if the list is too short.
  std::string build(const std::vector<unsigned>& degree, const std::vector<double>& coefficients) {
    coeff_ = coefficients;
    index_.clear();
    unsigned next = 0;
    for (unsigned d : degree) {
      std::vector<unsigned> idx(d);
      for (unsigned k = 0; k < d; ++k) idx[k] = next++;
      index_.push_back(std::move(idx));
    }
    if (next > coefficients.size())
      return "polynomialDegree asks for " + std::to_string(next) + " coefficients but polynomialStiffness has " +
             std::to_string(coefficients.size());
    return {};
  }
  std::size_t count() const { return index_.size(); }

  // SOFA's rule: spring i uses polynomial i when there is one per spring, else the first.
  unsigned polynomial_of(std::size_t spring, std::size_t springs) const {
    return count() == springs ? static_cast<unsigned>(spring) : 0u;
  }
  // The warning to give (once) when the first polynomial serves every spring, else empty.
  std::string first_for_all_warning(std::size_t springs) {
    if (count() == springs || warned_) return {};
    warned_ = true;
    return "polynomialDegree has " + std::to_string(count()) + " entries for " + std::to_string(springs) +
           " springs: every spring uses the first polynomial (as SOFA)";
  }

  double value(unsigned p, double s) const {
    double power = 1.0, result = 0.0;
    for (unsigned idx : index_[p]) {
      power *= s;
      result += coeff_[idx] * power;
    }
    return result;
  }
  double derivative(unsigned p, double s) const {
    double power = 1.0, result = 0.0;
    for (std::size_t k = 0; k < index_[p].size(); ++k) {
      result += static_cast<double>(k + 1) * coeff_[index_[p][k]] * power;
      power *= s;
    }
    return result;
  }

 private:
  std::vector<double> coeff_;
  std::vector<std::vector<unsigned>> index_;
  bool warned_ = false;
};

}  // namespace sinew
