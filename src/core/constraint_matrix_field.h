// The `constraint` Data of a mechanical state (SOFA's MechanicalObject::d_c):
// a read-only view of the state's constraint Jacobian (constraint_jacobian()),
// as the last constraint solve built it. Front ends read the rows directly
// (Python: a scipy.sparse matrix); the text lists the rows for display.
#pragma once

#include <string>

#include "core/field.h"

namespace sinew {

class MechanicalState;

class ConstraintMatrixField final : public BaseField {
 public:
  ConstraintMatrixField(MechanicalState* owner, Base* base)
      : BaseField(base, "constraint", "constraint Jacobian rows on this state (output of the constraint solver)",
                  "State"),
        state_(owner) {}
  MechanicalState& state() const { return *state_; }

  std::string type_name() const override { return "MatrixDeriv"; }
  std::string default_text() const override { return ""; }
  // One line per row: "row n dof v... dof v..." (n entries of width() values each).
  std::string text() const override;
  bool read(std::string_view text) override { return text.empty(); }  // an output: only "" is accepted

 protected:
  void copy_from(const BaseField&) override {}  // an output: links do not write it

 private:
  MechanicalState* state_;
};

}  // namespace sinew
