// The one explicit instantiation of Eigen::BDCSVD<Eigen::MatrixXd> that dpgen's tests and
// examples calling hig_update link (target dpgen_bdcsvd); they declare it extern
// (DPGEN_EXTERN_BDCSVD, dpgen/optim.hpp) and so do not compile Eigen's SVD each.
#include "dpgen/optim.hpp"

template class Eigen::BDCSVD<Eigen::MatrixXd>;
