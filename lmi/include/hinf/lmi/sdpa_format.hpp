// The LMI problem  minimise cᵀx  s.t.  M₀ + Σ xᵢMᵢ ⪯ 0  in SDPA sparse format, so that
// any SDP solver (CSDP, SDPA, …) can cross-check it. In SDPA's convention the problem
// is  min cᵀy  s.t.  Σ yᵢFᵢ − F₀ ⪰ 0,  so Fᵢ = −Mᵢ and F₀ = M₀.
#pragma once
#include <Eigen/Dense>
#include <string>

#include "hinf/lmi/lmi_problem.hpp"

namespace hinf::lmi {

std::string to_sdpa_sparse(const LmiProblem& lmi, const Eigen::VectorXd& c,
                           const std::string& comment);

}  // namespace hinf::lmi
