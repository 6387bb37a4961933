#include "solver/linear/ordering_method.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

OrderingMethod* find_or_create_ordering(Component& solver, Link<OrderingMethod>& link) {
  if (link) return link.get();
  Node* node = solver.node();
  if (OrderingMethod* o = node->find_local<OrderingMethod>()) {
    link.set(o);
    return o;
  }
  const ComponentInfo* info = registry().find("AMDOrderingMethod");
  if (!info) return nullptr;
  auto c = info->create({});
  c->set_type(info->name, {});
  c->name.set("AMDOrderingMethod" + std::to_string(node->next_default_index("AMDOrderingMethod")));
  c->where = solver.where;
  solver.msg_info("no ordering method found in the node: an AMDOrderingMethod is created");
  auto* o = dynamic_cast<OrderingMethod*>(node->add_object(std::move(c)));
  link.set(o);
  return o;
}

}  // namespace sinew

namespace sinew {
Eigen::SparseMatrix<double, Eigen::ColMajor, int> ordering_pattern(int n, const int* colptr, const int* rowind) {
  const int nnz = colptr[n];
  std::vector<double> ones(static_cast<std::size_t>(nnz), 1.0);
  Eigen::Map<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>> m(n, n, nnz, colptr, rowind, ones.data());
  return Eigen::SparseMatrix<double, Eigen::ColMajor, int>(m);
}
}  // namespace sinew
