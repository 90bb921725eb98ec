#include "fluid/fluid_exchange.hpp"

#include <KokkosBlas1_nrm2.hpp>

namespace rouleau {

double SingleRankExchange::norm(const ConstVector& x) const { return KokkosBlas::nrm2(x); }

}  // namespace rouleau
