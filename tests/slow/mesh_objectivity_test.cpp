// Mesh objectivity of the bare-core cyclic test (label slow: three full Girona runs).
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/protocol.hpp"

#include "support/brace_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace brb::analysis {
namespace {

TEST(BareCoreMesh, PeakForcesAndEnergyConvergeWithCoreElements) {
  // Reference: mesh convergence. With hardening and no softening the response must not
  // depend on the mesh: peak forces and dissipated energy change by < 2 % from 8 to 16 to
  // 32 core elements over the Girona protocol (inelastic in tension, buckling in compression).
  struct Figures {
    double tension, compression, energy;
  };
  std::vector<Figures> figures;
  for (const int elements : {8, 16, 32}) {
    model::BraceModel brace = model::build_brace_model(test::girona_d3_bare_core(elements));
    const io::LoadingProtocol protocol =
        io::girona_protocol(brace.yield_deformation, 2, brace.yield_deformation / 10.0);
    const CyclicTestResult result =
        run_cyclic_test(brace, protocol.deformation, protocol.cycle, protocol.cycle_amplitude);
    ASSERT_TRUE(result.completed) << elements << " elements: " << result.stop_reason;
    figures.push_back({result.max_tension, result.max_compression, result.energy_total});
  }
  for (std::size_t k = 1; k < figures.size(); ++k) {
    const Figures& coarse = figures[k - 1];
    const Figures& fine = figures[k];
    EXPECT_LT(std::abs(fine.tension / coarse.tension - 1.0), 0.02);
    EXPECT_LT(std::abs(fine.compression / coarse.compression - 1.0), 0.02);
    EXPECT_LT(std::abs(fine.energy / coarse.energy - 1.0), 0.02);
  }
}

} // namespace
} // namespace brb::analysis
