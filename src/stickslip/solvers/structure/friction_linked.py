"""A linear structure linked by one friction interface, in one direction, with constant N: solved exactly.

n degrees of freedom x [m], each relative to the ground, obey

    M ẍ + C ẋ + K x + d·((N/R)·s + F) = −M ι a_g(t),

M diagonal [kg], C [N·s/m] and K [N/m] the structure's own, ι = ones, the
ground acceleration a_g [m/s²] linear between samples, and one interface
whose slip is s = dᵀx (d has one +1 and at most one −1): a surface of radius
R [m] (R = ∞ flat) under the normal force N [N] gives the restoring force
(N/R)·s, and the friction force F obeys Coulomb's law, |F| ≤ μN and
F = μN·sign(ṡ) while it slips (docs/structures.md).  The isolated building
(d = e₀, the base) and the friction tuned mass damper (d = e_d − e_j) are
instances.

Each phase is linear with constant coefficients under a forcing linear in
time within a sample interval:

* **sliding** (σ = sign ṡ = ±1): M ẍ = −C ẋ − K_R x − M ι a − d σμN, with
  K_R = K + (N/R) d dᵀ;
* **holding** (ṡ = 0): the interface's degree of freedom eliminated,
  x = T y + s d/(dᵀd) with T an orthonormal basis of d⊥, so that
  ẍ = P (−C ẋ − K_R x − M ι a) with P = T (TᵀMT)⁻¹ Tᵀ, and F is the force the
  hold needs, F = dᵀr/(dᵀd) − (N/R)s with r = −M ι a − M ẍ − C ẋ − K x, linear
  in the held state and a.

With the augmented state w = (x, ẋ, u̇_g, a, ȧ, σμ) each phase is ẇ = Â_p w, so
that the state at any τ inside a sample interval is exp(Â_p τ) w (the first-
order hold of :mod:`~stickslip.solvers.structure.linear_response`, augmented
with the ground's velocity, for the ledger, and with the friction).  The
slide stops where ṡ = 0 (then it holds if |F| ≤ μN, else slides back along
F); the hold breaks where |F| reaches μN, sliding along F.  Events are searched
at :data:`~stickslip.solvers.structure.friction_linked_kernels.SEARCH_POINTS`
points per sub-interval of at most 1/16 of the shortest period of either
phase and located to round-off (:mod:`~stickslip.solvers.structure.friction_linked_kernels`).
The one approximation, as in the layer's exact scheme: a slide that stops and
starts again, or a hold that breaks and is held again, between two search
points (within 1/64 of the shortest period) is missed; the peaks are taken at
the samples, the search points and the events.

The ledger, in J (Uang and Bertero 1990, absolute, generalised):
E_k = ½ Σ mᵢ (u̇_g + ẋᵢ)², E_s = ½ xᵀKx, E_ζ = ∫ẋᵀCẋ dt, E_p = (N/2R)s²,
E_df = ∫F ṡ dt = μN·(path slid) and E_I = ∫(Σ mᵢ üᵢ,abs)·u̇_g dt, each
integrated on its own (E_ζ and E_I in closed form over every step: Van Loan's
integrals of a quadratic form of w), so that
E_k − E_k(0) + E_s + E_ζ + E_p + E_df − E_I closes to round-off.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from scipy import linalg

from stickslip.checks import checked_acceleration, checked_positive
from stickslip.errors import StickslipError
from stickslip.records.process import integrate_linear_acceleration
from stickslip.solvers.events import BLOCK, offsets, run_in_calls
from stickslip.solvers.structure import friction_linked_kernels as kernels


@dataclass(frozen=True)
class FrictionLinkedSystem:
    """A linear structure of n degrees of freedom with one friction interface (module docstring).

    Attributes
    ----------
    mass_matrix:
        M [kg], n × n, diagonal.
    damping_matrix:
        C [N·s/m], n × n, the structure's own.
    stiffness_matrix:
        K [N/m], n × n, the structure's own (no interface term).
    interface:
        d, n entries: the slip is s = dᵀx (one +1 and at most one −1).
    normal_force:
        N [N] on the interface, positive.
    radius:
        R [m] of the sliding surface; ``math.inf`` (the default) for a flat one.
    """

    mass_matrix: np.ndarray
    damping_matrix: np.ndarray
    stiffness_matrix: np.ndarray
    interface: np.ndarray
    normal_force: float
    radius: float = math.inf

    def __post_init__(self):
        mass = np.atleast_2d(np.asarray(self.mass_matrix, dtype=float))
        n = mass.shape[0]
        damping = np.asarray(self.damping_matrix, dtype=float).reshape(n, n)
        stiffness = np.asarray(self.stiffness_matrix, dtype=float).reshape(n, n)
        interface = np.asarray(self.interface, dtype=float).ravel()
        if mass.shape != (n, n) or not np.array_equal(mass, np.diag(np.diag(mass))) or np.any(np.diag(mass) <= 0):
            raise StickslipError("mass matrix M [kg]: expected a square diagonal matrix of positive masses")
        if interface.size != n or sorted(interface[interface != 0].tolist()) not in ([1.0], [-1.0, 1.0]):
            raise StickslipError(f"interface d: expected {n} entries with one +1 and at most one -1, got "
                                 f"{interface.tolist()}")
        if not (math.isfinite(self.normal_force) and self.normal_force > 0):
            raise StickslipError(f"normal force N [N] must be a positive finite number, got {self.normal_force!r}")
        if not self.radius > 0:
            raise StickslipError(f"radius of the sliding surface R [m] must be positive, got {self.radius!r}")
        for name, value in (("mass_matrix", mass), ("damping_matrix", damping), ("stiffness_matrix", stiffness),
                            ("interface", interface)):
            object.__setattr__(self, name, value)
        object.__setattr__(self, "normal_force", float(self.normal_force))
        object.__setattr__(self, "radius", float(self.radius))

    @property
    def size(self) -> int:
        """n, the degrees of freedom."""
        return self.interface.size

    @property
    def restoring_stiffness(self) -> float:
        """N/R [N/m], the surface's restoring stiffness (0 on a flat one)."""
        return self.normal_force / self.radius

    def phase_matrices(self) -> tuple[np.ndarray, np.ndarray]:
        """(Â_hold, Â_slide): the augmented state matrices (module docstring), m × m with m = 2n + 4."""
        n, mass, d = self.size, self.mass_matrix, self.interface
        stiffness = self.stiffness_matrix + self.restoring_stiffness * np.outer(d, d)
        ones = np.ones(n)
        basis = linalg.null_space(d[None, :])
        held = basis @ np.linalg.solve(basis.T @ mass @ basis, basis.T) if n > 1 else np.zeros((n, n))
        inverse = np.diag(1.0 / np.diag(mass))
        matrices = []
        for projector, friction in ((held, np.zeros(n)), (inverse, -inverse @ d * self.normal_force)):
            augmented = np.zeros((2 * n + 4, 2 * n + 4))
            augmented[:n, n:2 * n] = np.eye(n)
            augmented[n:2 * n, :n] = -projector @ stiffness
            augmented[n:2 * n, n:2 * n] = -projector @ self.damping_matrix
            augmented[n:2 * n, 2 * n + 1] = -projector @ mass @ ones
            augmented[n:2 * n, 2 * n + 3] = friction
            augmented[2 * n, 2 * n + 1] = 1.0      # u̇_g' = a
            augmented[2 * n + 1, 2 * n + 2] = 1.0  # a' = ȧ
            matrices.append(augmented)
        return matrices[0], matrices[1]

    def held_force_row(self, held: np.ndarray) -> np.ndarray:
        """The row f with F = f·w, the friction force [N] the hold needs (module docstring)."""
        n, mass, d = self.size, self.mass_matrix, self.interface
        residual = -mass @ held[n:2 * n]
        residual[:, :n] -= self.stiffness_matrix
        residual[:, n:2 * n] -= self.damping_matrix
        residual[:, 2 * n + 1] -= mass @ np.ones(n)
        row = d @ residual / (d @ d)
        row[:n] -= self.restoring_stiffness * d
        return row

    def interface_force_rows(self, held: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The rows of Q = (N/R)s + F [N] on w while holding and while sliding (F = σμN, σμ the last entry)."""
        n = self.size
        sliding = np.zeros(2 * n + 4)
        sliding[:n] = self.restoring_stiffness * self.interface
        sliding[-1] = self.normal_force
        holding = self.held_force_row(held).copy()
        holding[:n] += self.restoring_stiffness * self.interface
        return holding, sliding


def _exponential(matrix: np.ndarray) -> np.ndarray:
    """exp(``matrix``) by scaling and squaring its Taylor series in extended precision (NumPy's longdouble, 64
    mantissa bits on x86-64): the matrix halved until its 1-norm is at most 1/2, 24 terms (the rest below 1e-30 of
    the first), squared back, then rounded to double: within an ulp or so of the exact, as SciPy's expm.  Not
    SciPy's expm: each call of it wakes SciPy's BLAS threads, which then spin for about 0.1 s of processor time
    (measured on the 2-core machine), more than a sweep's setup."""
    norm = np.abs(matrix).sum(axis=0).max()
    squarings = max(0, math.ceil(math.log2(norm / 0.5))) if norm > 0.0 else 0
    scaled = matrix.astype(np.longdouble) / 2 ** squarings
    term = np.eye(matrix.shape[0], dtype=np.longdouble)
    total = term.copy()
    for k in range(1, 25):
        term = term @ scaled / k
        total += term
    for _ in range(squarings):
        total = total @ total
    return total.astype(float)


def _van_loan(pairs, step: float) -> list[tuple[np.ndarray, np.ndarray]]:
    """[(exp(Â δ), ∫₀^δ exp(Âᵀt) S exp(Ât) dt)] of each (Â, S) of ``pairs`` (Van Loan 1978, by :func:`_exponential`;
    S scaled to a largest entry of 1 there, the integral being linear in S, so that the forms' units do not set
    the exponential's scaling)."""
    size = pairs[0][0].shape[0]
    found = []
    for matrix, form in pairs:
        scale = np.abs(form).max() or 1.0
        block = np.zeros((2 * size, 2 * size))
        block[:size, :size] = -matrix.T
        block[:size, size:] = form / scale
        block[size:, size:] = matrix
        exponential = _exponential(block * step)
        step_matrix = exponential[size:, size:]
        found.append((step_matrix, scale * (step_matrix.T @ exponential[:size, size:])))
    return found


def _symmetric(left: np.ndarray, right: np.ndarray) -> np.ndarray:
    """S with wᵀSw = (left·w)(right·w)."""
    return 0.5 * (np.outer(left, right) + np.outer(right, left))


class _Kernels(NamedTuple):
    """The case's arrays for the kernels, and what the Python side reads back."""

    system: tuple
    matrices: np.ndarray
    forms: tuple
    tracked_rows: int


def _expansions(matrices: np.ndarray, rows: list[np.ndarray], terms: int) -> np.ndarray:
    """Per phase p the columns (m × K·(m + r), K = ``terms``) whose dots with w are the Taylor coefficients of
    exp(Â_p τ) w, Âᵏw/k! for k < K (entry i at column k·m + i), then those of each row ρ of ``rows[p]`` (r of them)
    on it, ρÂᵏw/k! (column K·m + j·K + k for the j-th row): one product with w gives the whole series an event's
    search needs (:func:`~stickslip.solvers.structure.friction_linked_kernels.interval_with_events`)."""
    tables = []
    for matrix, phase_rows in zip(matrices, rows):
        size = matrix.shape[0]
        powers = [np.eye(size)]
        for k in range(1, terms):
            powers.append(matrix @ powers[-1] / k)
        powers = np.stack(powers)  # (k, i, j): Âᵏ/k!
        state = powers.transpose(2, 0, 1).reshape(size, terms * size)
        on_rows = np.einsum("ri,kij->jrk", phase_rows, powers).reshape(size, -1)
        tables.append(np.hstack([state, on_rows]))
    return np.ascontiguousarray(np.stack(tables))


def _kernel_system(system: FrictionLinkedSystem, tracked, dts) -> _Kernels:
    """The tuple of arrays :func:`~stickslip.solvers.structure.friction_linked_kernels.interval_with_events` reads
    for records sampled every ``dts`` [s] (:func:`_expansions` to :func:`series_terms` of their longest search
    step, on the watched row of each phase, the hold's force and the slide's ṡ, and the ledger's two quadratic
    forms as pairs of rows (l, ρ), wᵀSw = Σ (l·w)(ρ·w): ẋᵀCẋ = Σᵢ ẋᵢ(Cẋ)ᵢ, then the input's (ιᵀM ü_abs)·u̇_g),
    with the matrices and the forms themselves for the Python side."""
    n, mass, d = system.size, system.mass_matrix, system.interface
    size = 2 * n + 4
    held, sliding = system.phase_matrices()
    matrices = np.stack([held, sliding])
    force_row = system.held_force_row(held)
    stop_row = np.zeros(size)
    stop_row[n:2 * n] = d
    damping = 0.5 * (system.damping_matrix + system.damping_matrix.T)
    viscous_form = np.zeros((size, size))
    viscous_form[n:2 * n, n:2 * n] = damping
    velocities, damped = np.zeros((n, size)), np.zeros((n, size))  # ẋᵀCẋ = Σᵢ ẋᵢ (Cẋ)ᵢ
    velocities[:, n:2 * n] = np.eye(n)
    damped[:, n:2 * n] = damping
    ground_velocity = np.zeros(size)
    ground_velocity[2 * n] = 1.0
    input_forms, watched_rows = [], []
    for matrix, watched in zip(matrices, (force_row, stop_row)):
        # Σ mᵢ üᵢ,abs = ιᵀM(ẍ + ι a), a row on w, times u̇_g
        inertia = np.ones(n) @ mass @ matrix[n:2 * n]
        inertia[2 * n + 1] += mass.sum()
        input_forms.append(_symmetric(inertia, ground_velocity))
        watched_rows.append(np.vstack([watched, velocities, damped, inertia, ground_velocity]))
    input_forms = np.stack(input_forms)
    tracked = np.zeros((0, 2 * n + 2)) if tracked is None else np.atleast_2d(np.asarray(tracked, dtype=float))
    if tracked.shape[1] != 2 * n + 2:
        raise StickslipError(f"tracked rows: expected {2 * n + 2} columns (x, x', a, Q), got {tracked.shape[1]}")
    slip = np.zeros(2 * n + 2)
    slip[:n] = d
    tracked = np.vstack([slip, tracked])
    rows = []
    for interface_row in system.interface_force_rows(held):
        on_w = np.zeros((tracked.shape[0], size))
        on_w[:, :2 * n] = tracked[:, :2 * n]
        on_w[:, 2 * n + 1] = tracked[:, 2 * n]
        on_w += np.outer(tracked[:, 2 * n + 1], interface_row)
        rows.append(on_w)
    longest = max(dt / search_points(matrices, dt) for dt in set(dts))
    arrays = (_expansions(matrices, watched_rows, series_terms(matrices, longest)), stop_row, force_row,
              np.stack(rows), system.normal_force, d, float(d @ d), n)
    return _Kernels(arrays, matrices, (viscous_form, input_forms), tracked.shape[0])


def _fastest(matrices: np.ndarray) -> float:
    """max|λ| [1/s] of the structure's part of either phase's matrix."""
    n = (matrices.shape[1] - 4) // 2
    return max(np.max(np.abs(np.linalg.eigvals(matrix[:2 * n, :2 * n]))) for matrix in matrices)


def search_points(matrices: np.ndarray, dt: float) -> int:
    """Search points per sample interval of ``dt`` [s]: SEARCH_POINTS per sub-interval of at most 1/16 of the
    shortest period 2π/max|λ| of either phase."""
    substeps = max(1, math.ceil(kernels.SUBSTEPS_PER_PERIOD * dt * _fastest(matrices) / (2.0 * math.pi)
                                * (1.0 - 1e-12)))
    return kernels.SEARCH_POINTS * substeps


def series_terms(matrices: np.ndarray, delta: float) -> int:
    """The Taylor terms K an event's step of at most ``delta`` [s] keeps: the fewest (at most TERMS) with
    (2ρδ)ᴷ/K! ≤ 1e-20, ρ = max|λ| of either phase, so that the first term left out of a series, and of the product
    of two (the ledger's integrands), is below 1e-20 of the first (11 for the benchmark's building at dt = 5 ms,
    where 2ρδ = 0.071; at most 14 where the search step is longest, 2ρδ = 2π/32)."""
    rate = 2.0 * _fastest(matrices) * delta
    terms, left_out = 1, rate
    while left_out > 1e-20 and terms < kernels.TERMS:
        terms += 1
        left_out *= rate / terms
    return terms


def _upper(form: np.ndarray) -> np.ndarray:
    """U, upper triangular, with wᵀUw = wᵀ S w: S's diagonal, and S_ij + S_ji above it."""
    return np.triu(form + form.T) - np.diag(np.diag(form))


def _dt_steps(arrays: _Kernels, dt: float, padded: int = 0) -> tuple:
    """For a record sampled every ``dt`` [s]: (δ, points, exp(Â_p δ), the viscous and input integrals over δ, the
    same three over dt (the integrals as :func:`_upper`'s U), and per phase the columns (m × (P + P·rows + 2n),
    P = max(points, ``padded``)) of the rows whose dots with w a quiet interval takes: per search point k the
    watched row (the hold's force, the slide's ṡ) times exp(Â_p kδ), then per point and tracked row the row times
    exp(Â_p kδ), then the (x, ẋ) rows of the interval's map)."""
    points = search_points(arrays.matrices, dt)
    delta = dt / points
    viscous_form, input_forms = arrays.forms
    stop_row, force_row, tracked, slips = arrays.system[1], arrays.system[2], arrays.system[3], arrays.system[6]
    size = arrays.matrices.shape[1]
    slip_row = np.zeros(size)
    slip_row[:arrays.system[7]] = arrays.system[5]
    steps, viscous, inputs, wholes, whole_viscous, whole_inputs = [], [], [], [], [], []
    watched = np.zeros((2, max(points, padded), size))
    tracked_at = np.zeros((2, max(points, padded), tracked.shape[1], size))
    exponentials = _van_loan([(matrix, form) for matrix, input_form in zip(arrays.matrices, input_forms)
                              for form in (viscous_form, input_form)], delta)
    for p, row in enumerate((force_row, stop_row)):
        (step, viscous_integral), (_, input_integral) = exponentials[2 * p:2 * p + 2]
        steps.append(step)
        viscous.append(viscous_integral)
        inputs.append(input_integral)
        # over the whole interval, composed of the search steps: the integrals as the search steps add them up
        power, whole_viscous_integral, whole_input_integral = np.eye(size), np.zeros((size, size)), np.zeros((size, size))
        for k in range(points):
            whole_viscous_integral += power.T @ viscous_integral @ power
            whole_input_integral += power.T @ input_integral @ power
            power = step @ power
            if p == 0:  # a hold keeps its slip exactly, as the kernel's steps put it back (_held)
                power -= (np.outer(slip_row, slip_row @ (power - np.eye(size)))
                          + np.outer(stop_row, stop_row @ power)) / slips
            watched[p, k] = row @ power
            tracked_at[p, k] = tracked[p] @ power
        wholes.append(power)
        whole_viscous.append(whole_viscous_integral)
        whole_inputs.append(whole_input_integral)
    n = arrays.system[7]
    columns = [np.vstack([watched[p], tracked_at[p].reshape(-1, size), wholes[p][:2 * n]]).T for p in range(2)]
    return (delta, points, np.stack(steps), np.stack(viscous), np.stack(inputs), np.stack(wholes),
            np.stack([_upper(form) for form in whole_viscous]), np.stack([_upper(form) for form in whole_inputs]),
            np.ascontiguousarray(np.stack(columns)))


def _held_modes(system: FrictionLinkedSystem, rows: np.ndarray) -> tuple[np.ndarray, ...]:
    """The held structure's static state at unit slip u_s (m entries), its modes' left rows ℓᵢ on w (real and
    imaginary parts), for each row r on w of ``rows`` |r·vᵢ| per mode and r·u_s (the bound of
    :func:`~stickslip.solvers.structure.friction_linked_kernels._skipped_block`), r·vᵢ itself, and the modes'
    λᵢ [1/s].

    The hold keeps the slip: x = s d/(dᵀd) + T y with T an orthonormal basis
    of d⊥, and y obeys TᵀMT ÿ + TᵀCT ẏ + TᵀK_R T y = −TᵀK_R d s/(dᵀd) (the ground
    is in f).  Where the modes are not a sound basis (a held structure
    without a static state, a defective or badly conditioned eigenvector
    matrix, or a mode that grows), every r·vᵢ is NaN: no hold off its rest
    state is passed."""
    n, d = system.size, system.interface
    size = 2 * n + 4
    stiffness = system.stiffness_matrix + system.restoring_stiffness * np.outer(d, d)
    basis = linalg.null_space(d[None, :])
    reduced_mass = basis.T @ system.mass_matrix @ basis
    reduced_stiffness = basis.T @ stiffness @ basis
    dofs = n - 1
    static = np.zeros(size)
    static[:n] = d / (d @ d)
    stiff = dofs == 0 or np.linalg.cond(reduced_stiffness) < 1e12
    if dofs and stiff:
        static[:n] -= basis @ np.linalg.solve(reduced_stiffness, basis.T @ stiffness @ d / (d @ d))
    reduced = np.zeros((2 * dofs, 2 * dofs))
    reduced[:dofs, dofs:] = np.eye(dofs)
    reduced[dofs:, :dofs] = -np.linalg.solve(reduced_mass, reduced_stiffness)
    reduced[dofs:, dofs:] = -np.linalg.solve(reduced_mass, basis.T @ system.damping_matrix @ basis)
    values, vectors = np.linalg.eig(reduced)
    to_reduced = np.zeros((2 * dofs, size))
    to_reduced[:dofs, :n] = basis.T
    to_reduced[dofs:, n:2 * n] = basis.T
    from_reduced = np.zeros((size, 2 * dofs))
    from_reduced[:n, :dofs] = basis
    from_reduced[n:2 * n, dofs:] = basis
    sound = dofs == 0 or (stiff and np.linalg.cond(vectors) < 1e6 and np.all(values.real <= 0.0))
    left = np.linalg.inv(vectors) @ to_reduced if sound else np.zeros((2 * dofs, size))
    complex_gains = rows @ from_reduced @ vectors if sound else np.full((rows.shape[0], 2 * dofs), math.nan)
    return (static, np.ascontiguousarray(left.real), np.ascontiguousarray(left.imag), np.abs(complex_gains),
            rows @ static, complex_gains, values)


def _skip_case(system: FrictionLinkedSystem, steps: tuple, modes: tuple, padded: int) -> tuple:
    """(Φ, the case's arrays of :func:`~stickslip.solvers.structure.friction_linked_kernels._skipped_block`) for a
    record of :func:`_dt_steps`' ``steps``: Φ the held sample interval's map, then Φᴮ (B the block), Σⱼ<B (Φʲ)ᵀGΦʲ
    of both ledger integrals, :func:`_held_modes`' arrays (the rows' r·vᵢ as real and imaginary parts) and
    e^{λᵢτ} at the block's search points τ = δ, 2δ, … (real and imaginary parts, B × ``padded`` per mode)."""
    held = steps[5][0]
    size = held.shape[0]
    n = system.size
    slip_row, stop_row = np.zeros(size), np.zeros(size)
    slip_row[:n] = system.interface
    stop_row[n:2 * n] = system.interface
    slips = system.interface @ system.interface
    step = held - (np.outer(slip_row, slip_row @ (held - np.eye(size))) + np.outer(stop_row, stop_row @ held)) / slips
    power = np.eye(size)
    sums = [np.zeros((size, size)), np.zeros((size, size))]
    for _ in range(BLOCK):
        for total, form in zip(sums, (steps[6][0], steps[7][0])):
            total += power.T @ form @ power
        power = step @ power
    static, left_real, left_imag, gains, static_values, complex_gains, values = modes
    times = steps[0] * np.arange(1, BLOCK * padded + 1)
    decays = np.exp(np.outer(values, times)) if values.size else np.zeros((0, times.size))
    return step, (power, sums[0], sums[1], static, left_real, left_imag, gains, static_values,
                  np.ascontiguousarray(complex_gains.real), np.ascontiguousarray(complex_gains.imag),
                  np.ascontiguousarray(decays.real), np.ascontiguousarray(decays.imag))


def _held_arrays(arrays: _Kernels, steps: tuple, step: np.ndarray, record: np.ndarray, slope: np.ndarray,
                 ground_velocity: np.ndarray, padded: int) -> tuple[np.ndarray, ...]:
    """:func:`~stickslip.solvers.structure.friction_linked_kernels.held_record`'s arrays of one record (the force
    and the tracked rows at the search points over ``padded`` points per interval)."""
    size = step.shape[0]
    blocks = (record.size - 1) // BLOCK + 1
    held = (np.zeros((blocks, size)), np.zeros(blocks), np.zeros((blocks, arrays.tracked_rows)),
            np.zeros(record.size), np.zeros(record.size), np.zeros((blocks, size)), np.zeros((blocks, size)),
            np.zeros((record.size, padded)), np.zeros((record.size, padded * arrays.tracked_rows)))
    kernels.held_record(arrays.system, steps, record, slope, ground_velocity, step, held)
    return held


def _checked_mu(mu) -> float:
    try:
        value = float(mu)
    except (TypeError, ValueError):
        value = math.nan
    if not (math.isfinite(value) and value >= 0.0):
        raise StickslipError(f"friction ratio mu must be a finite number >= 0, got {mu!r}")
    return value


def _ground(acceleration: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """(slope [m/s³] of each interval, 0 after the last sample; ground velocity [m/s] at the samples)."""
    slope = np.zeros_like(acceleration)
    slope[:-1] = np.diff(acceleration) / dt
    return slope, integrate_linear_acceleration(acceleration, dt)[0]


class FrictionLinkedHistory(NamedTuple):
    """The structure's response at every sample (arrays (samples, n) or (samples,)); energies in J."""

    displacement: np.ndarray
    """x [m], relative to the ground."""
    velocity: np.ndarray
    """ẋ [m/s], relative to the ground."""
    absolute_acceleration: np.ndarray
    """ẍ + a_g [m/s²]: M⁻¹(−Cẋ − Kx − d Q)."""
    slip: np.ndarray
    """s = dᵀx [m]."""
    friction_force: np.ndarray
    """F [N] just after each sample: σμN sliding, the force the hold needs holding."""
    interface_force: np.ndarray
    """Q = (N/R)s + F [N], the interface's whole force."""
    phase: np.ndarray
    """σ just after each sample: 0 holds, ±1 slides with ṡ ≷ 0."""
    kinetic_energy: np.ndarray
    strain_energy: np.ndarray
    viscous_energy: np.ndarray
    potential_energy: np.ndarray
    energy_dissipated: np.ndarray
    energy_input: np.ndarray
    balance_residual: np.ndarray
    """E_k − E_k(0) + E_s + E_ζ + E_p + E_df − E_I [J]."""
    sliding_path: np.ndarray
    """∫|ds| [m], cumulative."""
    slip_time: float
    """Time spent sliding [s]."""
    n_slip_episodes: int
    """Hold-to-slide transitions."""
    peak_slip: float
    """max |s| [m] over the samples, search points and events."""
    peaks: np.ndarray
    """max |row·(x, ẋ, a, Q)| of each tracked row, over the same points."""


def _ledger(system: FrictionLinkedSystem, displacement, velocity, ground_velocity, viscous, dissipated, inputs):
    """(E_k, E_s, E_p, residual) [J] at the samples from the state and the integrated terms."""
    masses = np.diag(system.mass_matrix)
    kinetic = 0.5 * ((ground_velocity[:, None] + velocity) ** 2) @ masses
    strain = 0.5 * np.einsum("ki,ij,kj->k", displacement, system.stiffness_matrix, displacement)
    potential = 0.5 * system.restoring_stiffness * (displacement @ system.interface) ** 2
    return kinetic, strain, potential, kinetic - kinetic[0] + strain + viscous + potential + dissipated - inputs


def friction_linked_history(system: FrictionLinkedSystem, acceleration, dt: float, mu: float,
                            tracked=None) -> FrictionLinkedHistory:
    """The exact response of ``system``, at rest at t = 0, to ``acceleration`` [m/s²] sampled every ``dt`` [s]
    with the friction ratio ``mu`` [1].

    ``tracked`` (optional) rows of 2n + 2 numbers, each a linear function of
    (x [m], ẋ [m/s], a_g [m/s²], Q [N]) whose peak magnitude is wanted
    (a story drift, a floor's absolute acceleration, a shear), reported in
    ``peaks`` in their order.
    """
    acceleration = checked_acceleration(acceleration, "acceleration")
    dt = checked_positive(dt, "time step dt [s]")
    mu = _checked_mu(mu)
    arrays = _kernel_system(system, tracked, [dt])
    slope, ground_velocity = _ground(acceleration, dt)
    n, samples = system.size, acceleration.size
    states = np.empty((samples, 2 * n))
    phases = np.empty(samples, dtype=np.int64)
    forces = np.empty(samples)
    totals = np.empty((samples, kernels.TOTALS))
    peaks = np.zeros(arrays.tracked_rows)
    kernels.record_history(arrays.system, _dt_steps(arrays, dt), acceleration, slope, ground_velocity, mu, states,
                           phases, forces, totals, peaks)
    displacement, velocity = states[:, :n], states[:, n:]
    slip = displacement @ system.interface
    interface_force = system.restoring_stiffness * slip + forces
    restoring = velocity @ system.damping_matrix.T + displacement @ system.stiffness_matrix.T
    absolute = -(restoring + np.outer(interface_force, system.interface)) / np.diag(system.mass_matrix)
    viscous, dissipated, inputs = (totals[:, kernels.VISCOUS], totals[:, kernels.DISSIPATED],
                                   totals[:, kernels.INPUT])
    kinetic, strain, potential, residual = _ledger(system, displacement, velocity, ground_velocity, viscous,
                                                   dissipated, inputs)
    return FrictionLinkedHistory(displacement, velocity, absolute, slip, forces, interface_force, phases, kinetic,
                                 strain, viscous, potential, dissipated, inputs, residual, totals[:, kernels.PATH],
                                 float(totals[-1, kernels.SLIP_TIME]), int(totals[-1, kernels.EPISODES]),
                                 float(peaks[0]), peaks[1:])


class FrictionLinkedSweep(NamedTuple):
    """End values of every (record, μ) pair: arrays (records, values); energies in J."""

    residual_slip: np.ndarray
    """s [m] at the end of the record."""
    peak_slip: np.ndarray
    """max |s| [m]."""
    kinetic_energy: np.ndarray
    """E_k at the end [J]."""
    strain_energy: np.ndarray
    viscous_energy: np.ndarray
    potential_energy: np.ndarray
    energy_dissipated: np.ndarray
    energy_input: np.ndarray
    balance_residual: np.ndarray
    """E_k − E_k(0) + E_s + E_ζ + E_p + E_df − E_I at the end [J]."""
    sliding_path: np.ndarray
    slip_time: np.ndarray
    n_slip_episodes: np.ndarray
    peaks: np.ndarray
    """(records, values, rows): max |row·(x, ẋ, a, Q)| of each tracked row."""


def friction_linked_sweep(system: FrictionLinkedSystem, records, dts, mus, tracked=None) -> FrictionLinkedSweep:
    """End values of ``system`` for every record (ground accelerations [m/s²], sampled every ``dts`` [s]) and
    every friction ratio of ``mus`` [1], in parallel on the event engine's sweep lanes (no history arrays).

    Equal to :func:`friction_linked_history`'s end values to round-off; ``tracked`` as there.
    """
    records = [checked_acceleration(record, f"record {index}") for index, record in enumerate(records)]
    dts = np.array([checked_positive(dt, "time step dt [s]") for dt in np.broadcast_to(dts, len(records))])
    columns = np.array([[_checked_mu(mu)] for mu in np.atleast_1d(mus)])
    arrays = _kernel_system(system, tracked, dts.tolist())
    n = system.size
    sizes = np.array([record.size for record in records], dtype=np.int64)
    record_offsets = offsets(sizes)
    grounds = [_ground(record, dt) for record, dt in zip(records, dts)]
    most = max(search_points(arrays.matrices, dt) for dt in set(dts.tolist()))
    by_dt = {dt: _dt_steps(arrays, dt, most) for dt in set(dts.tolist())}
    steps = [by_dt[dt] for dt in dts.tolist()]
    force_and_tracked = np.vstack([arrays.system[2], arrays.system[3][0]])
    modes = _held_modes(system, force_and_tracked)
    skip_by_dt = {dt: _skip_case(system, dt_steps, modes, most) for dt, dt_steps in by_dt.items()}
    skips = [skip_by_dt[dt][1] for dt in dts.tolist()]
    helds = [_held_arrays(arrays, by_dt[dt], skip_by_dt[dt][0], record, slope, velocity, most)
             for record, dt, (slope, velocity) in zip(records, dts.tolist(), grounds)]
    block_offsets = offsets(np.array([held[0].shape[0] for held in helds], dtype=np.int64))
    group = (np.concatenate(records), record_offsets, np.concatenate([slope for slope, _ in grounds]),
             np.concatenate([velocity for _, velocity in grounds]), np.array([step[0] for step in steps]),
             np.array([step[1] for step in steps], dtype=np.int64),
             *(np.stack([step[k] for step in steps]) for k in range(2, 9)), block_offsets,
             *(np.concatenate([held[k] for held in helds]) for k in range(9)),
             *(np.stack([skip[k] for skip in skips]) for k in range(12)), *arrays.system)
    width = 2 * n + 1 + kernels.TOTALS
    out = np.zeros((len(records), columns.shape[0], width + arrays.tracked_rows))
    run_in_calls(lambda first, last: kernels.sweep_pairs(group, columns, first, last, out),
                 np.repeat(sizes * np.array([step[1] for step in steps]), columns.shape[0]))
    displacement, velocity = out[..., :n], out[..., n:2 * n]
    totals = out[..., 2 * n + 1:width]
    final_ground = np.array([velocity_[-1] for _, velocity_ in grounds])[:, None]
    masses = np.diag(system.mass_matrix)
    kinetic = 0.5 * ((final_ground[..., None] + velocity) ** 2) @ masses
    strain = 0.5 * np.einsum("rci,ij,rcj->rc", displacement, system.stiffness_matrix, displacement)
    slip = displacement @ system.interface
    potential = 0.5 * system.restoring_stiffness * slip ** 2
    viscous, dissipated, inputs = (totals[..., kernels.VISCOUS], totals[..., kernels.DISSIPATED],
                                   totals[..., kernels.INPUT])
    return FrictionLinkedSweep(slip, out[..., width], kinetic, strain, viscous, potential, dissipated, inputs,
                               kinetic + strain + viscous + potential + dissipated - inputs,
                               totals[..., kernels.PATH], totals[..., kernels.SLIP_TIME],
                               totals[..., kernels.EPISODES].astype(np.int64), out[..., width + 1:])
