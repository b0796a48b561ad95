"""The planted physics bugs of the mutation suite (docs/testing.md, "The suite catches
planted bugs"). Each is one exact text substitution in one source file: `old` must occur
exactly once in `file` (runMutations.py refuses the whole list otherwise, so the list
cannot rot silently when the code moves), `new` is what a careless edit could have left.
`catchers` are ctest regexes of the default-label tests expected to catch it; they run
first, the rest of the default labels after them. `why` says what the bug breaks.
"""

from collections import namedtuple

Mutation = namedtuple("Mutation", "name file old new catchers why")

MUTATIONS = [
    Mutation("volumeCorrectionSign", "libsph/effects/VolumeCorrection.cpp",
             "    dr[i] += coeff * sum;", "    dr[i] -= coeff * sum;",
             [r"^unit\.test_effects_volumeCorrection$", r"^regression\.hydrostaticTank$"],
             "eq. 17 pushes particles toward compressed regions: the interior density error grows"),
    Mutation("viscosityHalved", "libsph/effects/Viscosity.cpp",
             "addVelocityLaplacian(s.neighbours, s.weights, nu_ * s.V(),",
             "addVelocityLaplacian(s.neighbours, s.weights, 0.5 * nu_ * s.V(),",
             [r"^unit\.test_effects_viscosity$", r"^regression\.poiseuilleStartup$"],
             "the viscous acceleration nu <lap u> (eq. 4) is half what it should be"),
    Mutation("opsShiftTripled", "libsph/effects/ShiftingDistribution.cpp",
             "const double coeff = ops ? -this->par_.C * h * h * V",
             "const double coeff = ops ? -3 * this->par_.C * h * h * V",
             [r"^stability\.", r"^unit\.test_effects_ops$", r"^regression\.damBreak$"],
             "the OPS shift (eq. 11) is three times too long (C = 0.6, past the 0.5 stability limit)"),
    Mutation("vicinityPressureZero", "libsph/pressure/PressureEquation.cpp",
             "isUnknown = !(c == SurfaceClass::free || c == SurfaceClass::splash);",
             "isUnknown = !(c == SurfaceClass::free || c == SurfaceClass::splash || c == SurfaceClass::vicinity);",
             [r"^regression\.hydrostaticTank$", r"^comparison\.rotatingSquarePatch$"],
             "vicinity particles get the free-surface condition p = 0: the surface layer is two h thick"),
    Mutation("kernelConstant2D", "libsph/kernels/Kernel.cpp",
             "sigma_ = (D == 2 ? 10.0 / (7.0 * M_PI) : 1.0 / M_PI) / hD;",
             "sigma_ = (D == 2 ? 1.02 * 10.0 / (7.0 * M_PI) : 1.0 / M_PI) / hD;",
             [r"^unit\.test_kernels$", r"^stability\."],
             "the 2D cubic-spline normalisation 10/(7 pi h^2) is 2 % too large: <rho> reads 2 % high"),
    Mutation("adamiWallTermDropped", "libsph/boundaries/WallParticles.cpp",
             "  if (row.weightSum > 0) row.rhs = s.rho0 * sum / row.weightSum;\n",
             "",
             [r"^regression\.hydrostaticTank$"],
             "wall pressure is the Shepard average of the fluid's, without rho (g - a_w) . r: no hydrostatic wall pressure"),
    Mutation("pressureGradientSign", "libsph/operators/Ops.cpp",
             "  sumOverNeighbours(nl, &rows, scale, true, out,\n"
             "                    [&](long i, Index k) -> Vec<D> { return (f[nl.j[k]] - f[i]) * pw.gradW[k]; });",
             "  sumOverNeighbours(nl, &rows, scale, true, out,\n"
             "                    [&](long i, Index k) -> Vec<D> { return (f[nl.j[k]] + f[i]) * pw.gradW[k]; });",
             [r"^unit\.test_isph_hydrostatic$", r"^regression\.hydrostaticTank$"],
             "the corrector's pressure gradient (eq. 5) uses p_j + p_i: not zero for a uniform pressure"),
    Mutation("shiftCapTenfold", "libsph/effects/ParticleShifting.cpp",
             "capShift(dr_, maxShift_ * s.h);",
             "capShift(dr_, 10 * maxShift_ * s.h);",
             [r"^unit\.test_effects_shiftCap$", r"^stability\."],
             "the shift cap of eq. 10 is h instead of 0.1 h"),
    Mutation("sph2CorrectionDropped", "libsph/operators/DerivativeOperator.cpp",
             "if (row == 1 && weights::fiRow(lim, h, V, nl, b, e, out)) return weights::orderFI;",
             "if (row == 0 && weights::fiRow(lim, h, V, nl, b, e, out)) return weights::orderFI;",
             [r"^unit\.test_operators_exactness$", r"^regression\.spaceOrder$"],
             "the SPH(2) full-inverse correction (docs/method.md 3.2) is never used: first order only"),
    Mutation("cflDoubled", "libsph/isph/TimeLoop.cpp",
             "{umax > 0 ? rc_.maxCo * s_.h / umax : INFINITY, \"CFL\"},",
             "{umax > 0 ? 2 * rc_.maxCo * s_.h / umax : INFINITY, \"CFL\"},",
             [r"^unit\.test_isph_timeStep$", r"^stability\."],
             "the Courant limit dt <= maxCo h / max|u| (docs/method.md 4.3) is twice too large"),
    Mutation("gravityTwice", "libsph/effects/Gravity.cpp",
             "      if (s.isFluid(i)) acc[i] += g_;",
             "      if (s.isFluid(i)) acc[i] += 2 * g_;",
             [r"^unit\.test_isph_hydrostatic$", r"^regression\.hydrostaticTank$"],
             "gravity added twice in the predictor (eq. 4)"),
    Mutation("xsphCoefficientDoubled", "libsph/effects/XSPH.cpp",
             "const double c = epsilon_ * s.V();",
             "const double c = 2 * epsilon_ * s.V();",
             [r"^unit\.test_effects_xsph$"],
             "the XSPH velocity (docs/method.md 10) uses 2 epsilon"),
    Mutation("freeSurfaceThresholdLow", "libsph/surface/FreeSurface.cpp",
             "else if (div < par_.candidateThreshold) c = SurfaceClass::free;",
             "else if (div < par_.candidateThreshold - 0.25) c = SurfaceClass::free;",
             [r"^regression\.hydrostaticTank$", r"^regression\.rotatingSquarePatch$"],
             "free-surface candidates need div r < 1.5 instead of 1.75 (docs/method.md 5.1): surface particles missed"),
]
