!> Floquet stability of the torsion of a platform with inextensible cables (n = 3; module
!! platform_model): the periodic orbit, found by shooting, and its multipliers.
!! doc/theory.md, "Floquet analysis of a platform's torsion".
!!
!! The orbit.  The brake orbit of the torsion (module platform_orbit: from rest at
!! yaw = rest + amplitude to the half period where yaw' returns to 0, by shooting from the
!! turn about the mass centre, by continuation in the offset from the centred body's pure
!! torsion where that fails), with its half-period map.  The orbit's closure is its
!! residual, the rates at t_h (orbit_closure).
!!
!! The multipliers.  The half-period map N = dy(t_h)/dy(0) comes with the orbit: the
!! orbit's forward sensitivities to its start (identity columns) in the integrator's error
!! control.  The monodromy is R N^-1 R N (R = diag(I, -I), both ends at rest), whose two
!! multipliers 1 by structure (the time shift and the energy: a Jordan block, which spreads
!! computed eigenvalues by the square root of the error) are removed by reducing to the
!! subspace S orthogonal to grad E and the flow f at both ends, as module floquet does for
!! the bifilar (U0, Uh bases of S at the ends, P the projection along f there): the four
!! others are the eigenvalues of the pencil (Rh N4, N4 R0), N4 = Uh^T P N U0 (floquet's
!! pencil_multipliers).  The orbit is stable when the largest modulus is at most
!! 1 + STABILITY_MARGIN.  trivial_residual: grad E(y(t_h))^T N U0 (exactly 0), relative.
module platform_floquet
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_MODEL, ERR_NUMERIC
    use text, only: sci, itoa
    use ode_system, only: integrator_t, integrator_stats_t
    use integrators, only: new_integrator, SOLVER_LSODA
    use floquet, only: pencil_multipliers, STABILITY_MARGIN, CHART_INVALID, CHART_FAILED
    use platform_orbit, only: ORBIT_NS, platform_orbit_t, platform_orbit_find, orbit_flow
    use platform_geometry, only: platform_t, platform_prepare, QPSI
    use platform_model, only: platform_sys_t, platform_start, potential_gradient, rest_pose, &
                              platform_motion_t, platform_evaluate
    implicit none
    private

    integer, parameter :: NS = ORBIT_NS

    !> One Floquet analysis of a platform's torsion.
    type, public :: platform_floquet_t
        real(dp) :: period = 0.0_dp             !! T (the deck's unit of time)
        real(dp) :: max_modulus = 0.0_dp        !! largest |multiplier| of the four
        logical :: stable = .false.             !! max_modulus <= 1 + STABILITY_MARGIN
        complex(dp) :: multipliers(NS) = (0.0_dp, 0.0_dp)  !! the four, by modulus; two 1
        logical :: trivial(NS) = .false.        !! the two that are 1 by structure
        real(dp) :: y0(NS) = 0.0_dp             !! the turning point at t = 0 (at rest)
        real(dp) :: yh(NS) = 0.0_dp             !! the turning point at T/2
        real(dp) :: orbit_closure = 0.0_dp      !! max |x'|, |y'| at T/2 (rates' units)
        real(dp) :: trivial_residual = 0.0_dp
        integer :: shooting_iterations = 0      !! Newton's iterations (0: pure torsion)
        integer :: continuation_steps = 0       !! steps in the offset (0: none needed)
        integer :: steps = 0, rhs_evaluations = 0   !! the integrations', all of them
    end type platform_floquet_t

    public :: platform_floquet_analysis, platform_floquet_point, platform_point_ready

contains

    !> A chart's or a design's rig ready for the Floquet analysis: prepared, its rest pose
    !! found (an equilibrium, stable or not), every cable taut there.  ok = .false. when not
    !! (the cables cannot hold the body: the point has no torsion to analyse).
    subroutine platform_point_ready(pl, ok)
        type(platform_t), intent(inout) :: pl
        logical, intent(out) :: ok
        type(status_t) :: st
        type(platform_motion_t) :: mo
        real(dp) :: y(NS)
        ok = .false.
        if (pl%n /= 3) return
        call platform_prepare(pl, st)
        if (st%code /= STATUS_OK) return
        call rest_pose(pl, st)
        if (st%code /= STATUS_OK) return
        y = 0.0_dp
        y(1:3) = pl%q_ref(pl%free(1:3))
        call platform_evaluate(pl, y, mo, st)
        if (st%code /= STATUS_OK) return
        ok = all(mo%tension(1:3) > 0.0_dp)
    end subroutine platform_point_ready

    !> The Floquet analysis of the torsion of amplitude amp (rad) of platform pl (n = 3,
    !! inextensible; checked: check_platform or platform_point_ready) by method (SOLVER_LSODA,
    !! SOLVER_RADAU) at tolerance rtol.  ERR_MODEL when no periodic torsion is found (the
    !! shooting and the continuation fail) or the model fails on the way (a slack cable).
    subroutine platform_floquet_analysis(pl, amp, rtol, method, res, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: amp             !! yaw amplitude (rad)
        real(dp), intent(in) :: rtol
        integer, intent(in) :: method
        type(platform_floquet_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        type(platform_orbit_t) :: orb
        call platform_orbit_find(pl, amp, rtol, method, 'platform floquet', orb, stat)
        res%shooting_iterations = orb%shooting_iterations
        res%continuation_steps = orb%continuation_steps
        res%steps = orb%steps
        res%rhs_evaluations = orb%rhs_evaluations
        if (stat%code /= STATUS_OK) return
        res%y0 = orb%y0
        res%yh = orb%yh
        res%period = 2.0_dp*orb%th
        res%orbit_closure = maxval(abs(orb%yh(4:5)))
        call multipliers(pl, orb%y0, orb%yh, orb%n, res, stat)
    end subroutine platform_floquet_analysis

    !> The four non-trivial multipliers from the half-period map n (see the module's
    !! header), the two trivial ones 1.
    subroutine multipliers(pl, y0, yh, n, res, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: y0(NS), yh(NS), n(NS, NS)
        type(platform_floquet_t), intent(inout) :: res
        type(status_t), intent(out) :: stat
        real(dp) :: g0(NS), gh(NS), f0(NS), fh(NS), u0(NS, 4), uh(NS, 4), pf(NS, NS), &
                    n4(4, 4), r0(4, 4), rh(4, 4), rr(NS), nu(NS, 4), v
        complex(dp) :: lam(4)
        integer :: k
        g0 = 0.0_dp
        gh = 0.0_dp
        call potential_gradient(pl, y0(1:3), g0(1:3), v, stat)
        if (stat%code /= STATUS_OK) return
        call potential_gradient(pl, yh(1:3), gh(1:3), v, stat)
        if (stat%code /= STATUS_OK) return
        call orbit_flow(pl, y0, f0, stat)
        if (stat%code /= STATUS_OK) return
        call orbit_flow(pl, yh, fh, stat)
        if (stat%code /= STATUS_OK) return
        ! at rest the flow is (0, a); exactly so: the rates are the closure's residual
        f0(1:3) = 0.0_dp
        fh(1:3) = 0.0_dp
        call complement4(g0, f0, u0)
        call complement4(gh, fh, uh)
        pf = -spread(fh, 2, NS)*spread(fh, 1, NS)/dot_product(fh, fh)
        do k = 1, NS
            pf(k, k) = pf(k, k) + 1.0_dp
        end do
        nu = matmul(n, u0)
        n4 = matmul(transpose(uh), matmul(pf, nu))
        rr = [1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, -1.0_dp]
        r0 = matmul(transpose(u0), spread(rr, 2, 4)*u0)
        rh = matmul(transpose(uh), spread(rr, 2, 4)*uh)
        call pencil_multipliers(n4, r0, rh, lam, stat)
        if (stat%code /= STATUS_OK) return
        res%multipliers(1:4) = lam
        res%trivial(1:4) = .false.
        res%multipliers(5:6) = (1.0_dp, 0.0_dp)
        res%trivial(5:6) = .true.
        res%max_modulus = maxval(abs(lam))
        res%stable = res%max_modulus <= 1.0_dp + STABILITY_MARGIN
        res%trivial_residual = norm2(matmul(gh, nu))/norm2(gh)/max(1.0_dp, norm2(nu))
    end subroutine multipliers

    !> An orthonormal basis u of the complement of a and b (each scaled to unit length
    !! first: they may be small near the rest), by modified Gram-Schmidt twice, the unit
    !! vectors completing the basis kept when well independent.
    subroutine complement4(a, b, u)
        real(dp), intent(in) :: a(NS), b(NS)
        real(dp), intent(out) :: u(NS, 4)
        real(dp) :: q(NS, NS), v(NS)
        integer :: k, j, nq, pass
        nq = 0
        call add(a/norm2(a), 1.0e-12_dp)
        call add(b/norm2(b), 1.0e-12_dp)
        do k = 1, NS
            v = 0.0_dp
            v(k) = 1.0_dp
            call add(v, 1.0e-3_dp)
        end do
        u = q(:, 3:NS)
    contains
        subroutine add(w, keep)
            real(dp), intent(in) :: w(NS), keep
            if (nq == NS) return
            v = w
            do pass = 1, 2
                do j = 1, nq
                    v = v - dot_product(q(:, j), v)*q(:, j)
                end do
            end do
            if (norm2(v) > keep) then
                nq = nq + 1
                q(:, nq) = v/norm2(v)
            end if
        end subroutine add
    end subroutine complement4

    !> One point of a platform's chart or design: the largest multiplier and the period of
    !! its torsion at amp_deg, or a sentinel in both: CHART_INVALID where there is no
    !! torsion to analyse (the cables cannot hold the body, no periodic torsion found),
    !! CHART_FAILED where the analysis failed (the integrator).  pl as platform_of gives it
    !! (platform_point_ready is called here).  Never stops, never NaN.
    subroutine platform_floquet_point(pl_in, amp_deg, rtol, method, modulus, period)
        type(platform_t), intent(in) :: pl_in
        real(dp), intent(in) :: amp_deg, rtol
        integer, intent(in) :: method
        real(dp), intent(out) :: modulus, period
        type(platform_t) :: pl
        type(platform_floquet_t) :: res
        type(status_t) :: st
        logical :: ok
        modulus = CHART_INVALID
        period = CHART_INVALID
        pl = pl_in
        call platform_point_ready(pl, ok)
        if (.not. ok) return
        call platform_floquet_analysis(pl, amp_deg*deg, rtol, method, res, st)
        if (st%code == STATUS_OK) then
            modulus = res%max_modulus
            period = res%period
        else if (st%code /= ERR_DECK .and. st%code /= ERR_MODEL) then
            modulus = CHART_FAILED
            period = CHART_FAILED
        end if
    end subroutine platform_floquet_point

end module platform_floquet
