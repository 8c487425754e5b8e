!> Floquet stability of pure torsion, Kane & Tseng (1966) eqs. (45)-(51).
!!
!! With equal cables, the mass centre on the vertical bisector of AB and a principal axis
!! vertical, pure torsion is an exact periodic motion.  Its period t* comes from the energy
!! integral of the one-degree-of-freedom motion (eqs. (45)-(48), generalised to b /= b'):
!!     t* = 4 int_0^A sqrt(J(q) / (2 (z(A) - z(q)))) dq,   J = I_v + z'(q)^2,
!! with z(q) the height of the body as it turns by q and I_v its vertical moment of inertia,
!! evaluated by Gauss-Legendre quadrature after q = A sin(phi), which removes the endpoint
!! singularity.  The variational equations (51), dH/dt = Z H, are integrated along the orbit
!! over half a period in the regular chart of bifilar_model (the orbit lies on theta2 = 0,
!! where the paper's coordinates are singular), in `nseg` shooting segments; reversibility
!! gives the other half, and the six non-trivial multipliers are the generalized eigenvalues
!! of a 6 x 6 pencil of the half-period map N = H(t*/2) reduced to the subspace S of the
!! non-trivial motions (reversible_multipliers, LAPACK DGGEV).  Z is the exact Jacobian of
!! the chart right-hand side (see jacobian_z).
!!
!! By default (SENS_FORWARD) the multipliers need N only on S: the six columns N U0 (U0 a
!! basis of S at the start) are the orbit's forward sensitivities to its initial state
!! along U0, the integrator's staggered direct method (ode_system's sens_init): at each
!! step's converged point Z, computed once, solves the step's formula for them, and they
!! take part in the error control (the orbit alone would set steps too long for the motions
!! about it).  floquet_analysis' whole_map integrates all ten columns of N that way (the
!! monodromy H(t*) then in the result).  With SENS_DIFFERENCES (&integration sensitivities
!! = 'differences') the orbit and the whole N are one system of 110 equations under the
!! error control, Z evaluated at every right-hand side (variational_t), as before.
module floquet
    use kinds, only: dp, pi, deg
    use finite, only: finite_bits
    use status, only: status_t, set_error, ERR_DECK, ERR_NUMERIC, ERR_MODEL
    use ode_system, only: ode_system_t, integrator_t, integrator_stats_t
    use geometry, only: pendulum_t, constraint_g, beta_coeffs
    use start_pose, only: raised_angles, solve_theta5
    use bifilar_model, only: chart_accelerations, chart_state, chart_invariant_gradients, &
                             chart_jacobian, NSTATE, bifilar_t
    use text, only: sci
    use integrators, only: new_integrator, SOLVER_LSODA, SENS_FORWARD, SENS_DIFFERENCES
    use lapack_wrap, only: la_eig, la_geig, la_lu_factor, la_lu_solve, la_lu_solve_many
    use unused_arg, only: unused
    implicit none
    private

    integer, parameter :: NV = NSTATE + NSTATE*NSTATE   !! orbit + monodromy columns
    !> Largest |sin theta2| of cable BC the model is analysed at (kane_run's SIN2_MAX: a run
    !! beyond it stops with exit status 4)
    real(dp), parameter :: SIN2_LIMIT = 0.9999_dp

    !> The orbit and its variational equations as one ODE system.  Its stiff-method iteration
    !! matrix is I - h l0 diag(Z, ..., Z) (the coupling of H to the orbit left out, see
    !! variational_factor): the system factors the one 10 x 10 block and solves the 11
    !! blocks with it (ode_system's structured iteration), never a 110 x 110 matrix.
    type, extends(ode_system_t), public :: variational_t
        type(pendulum_t) :: p
        real(dp) :: lu(NSTATE, NSTATE) = 0.0_dp     !! LU factors of I - h l0 Z
        integer :: ipiv(NSTATE) = 0                 !! their pivots
    contains
        procedure :: rhs => variational_rhs
        procedure :: has_iteration_solver => variational_structured
        procedure :: factor_iteration => variational_factor
        procedure :: solve_iteration => variational_solve
    end type variational_t

    !> Result of one Floquet analysis.
    type, public :: floquet_result_t
        real(dp) :: period = 0.0_dp             !! t* in units of tau
        real(dp) :: max_modulus = 0.0_dp        !! largest |multiplier| among the non-trivial
        logical :: stable = .false.             !! max_modulus <= 1 + stability_margin
        complex(dp) :: multipliers(NSTATE) = (0.0_dp, 0.0_dp)  !! non-trivial first, by modulus
        logical :: trivial(NSTATE) = .false.    !! the four multipliers that are 1 by structure
        real(dp) :: orbit_closure = 0.0_dp      !! |y(t*) - y(0)|, max norm
        !> largest relative residual of the trivial identities on the computed map (see
        !! floquet_analysis)
        real(dp) :: trivial_residual = 0.0_dp
        !> H(t*) of the chart form, when the whole 10 x 10 map was integrated (floquet_analysis
        !! with whole_map or sensitivities = SENS_DIFFERENCES; multipliers_from_monodromy);
        !! else 0
        real(dp) :: monodromy(NSTATE, NSTATE) = 0.0_dp
        integer :: steps = 0, rhs_evaluations = 0
    end type floquet_result_t

    real(dp), parameter, public :: STABILITY_MARGIN = 1.0e-6_dp

    !> The 48-point Gauss-Legendre rule on [-1, 1] of torsion_period: the roots of P_48
    !! (in the order cos(pi (i - 1/4)/(48 + 1/2)), largest first) and their weights
    !! 2/((1 - x^2) P_48'(x)^2), computed to 40 digits by Newton's method on the recurrence
    !! of the Legendre polynomials (test `floquet: Gauss-Legendre table` recomputes them).
    real(dp), parameter, public :: GL_X(48) = [ &
        9.9877100725242611860e-1_dp, 9.9353017226635075755e-1_dp, &
        9.8412458372282685774e-1_dp, 9.7059159254624725046e-1_dp, &
        9.5298770316043086072e-1_dp, 9.3138669070655433311e-1_dp, &
        9.0587913671556967282e-1_dp, 8.7657202027424788591e-1_dp, &
        8.4358826162439353071e-1_dp, 8.0706620402944262708e-1_dp, &
        7.6715903251574033925e-1_dp, 7.2403413092381465467e-1_dp, &
        6.7787237963266390521e-1_dp, 6.2886739677651362400e-1_dp, &
        5.7722472608397270382e-1_dp, 5.2316097472223303368e-1_dp, &
        4.6690290475095840454e-1_dp, 4.0868648199071672992e-1_dp, &
        3.4875588629216073816e-1_dp, 2.8736248735545557674e-1_dp, &
        2.2476379039468906122e-1_dp, 1.6122235606889171806e-1_dp, &
        9.7004699209462698930e-2_dp, 3.2380170962869362033e-2_dp, &
        -3.2380170962869362033e-2_dp, -9.7004699209462698930e-2_dp, &
        -1.6122235606889171806e-1_dp, -2.2476379039468906122e-1_dp, &
        -2.8736248735545557674e-1_dp, -3.4875588629216073816e-1_dp, &
        -4.0868648199071672992e-1_dp, -4.6690290475095840454e-1_dp, &
        -5.2316097472223303368e-1_dp, -5.7722472608397270382e-1_dp, &
        -6.2886739677651362400e-1_dp, -6.7787237963266390521e-1_dp, &
        -7.2403413092381465467e-1_dp, -7.6715903251574033925e-1_dp, &
        -8.0706620402944262708e-1_dp, -8.4358826162439353071e-1_dp, &
        -8.7657202027424788591e-1_dp, -9.0587913671556967282e-1_dp, &
        -9.3138669070655433311e-1_dp, -9.5298770316043086072e-1_dp, &
        -9.7059159254624725046e-1_dp, -9.8412458372282685774e-1_dp, &
        -9.9353017226635075755e-1_dp, -9.9877100725242611860e-1_dp]
    real(dp), parameter, public :: GL_W(48) = [ &
        3.1533460523058386327e-3_dp, 7.3275539012762621024e-3_dp, &
        1.1477234579234539490e-2_dp, 1.5579315722943848728e-2_dp, &
        1.9616160457355527814e-2_dp, 2.3570760839324379141e-2_dp, &
        2.7426509708356948200e-2_dp, 3.1167227832798088902e-2_dp, &
        3.4777222564770438893e-2_dp, 3.8241351065830706317e-2_dp, &
        4.1545082943464749214e-2_dp, 4.4674560856694280419e-2_dp, &
        4.7616658492490474826e-2_dp, 5.0359035553854474958e-2_dp, &
        5.2890189485193667096e-2_dp, 5.5199503699984162868e-2_dp, &
        5.7277292100403215705e-2_dp, 5.9114839698395635746e-2_dp, &
        6.0704439165893880053e-2_dp, 6.2039423159892663904e-2_dp, &
        6.3114192286254025657e-2_dp, 6.3924238584648186624e-2_dp, &
        6.4466164435950082207e-2_dp, 6.4737696812683922503e-2_dp, &
        6.4737696812683922503e-2_dp, 6.4466164435950082207e-2_dp, &
        6.3924238584648186624e-2_dp, 6.3114192286254025657e-2_dp, &
        6.2039423159892663904e-2_dp, 6.0704439165893880053e-2_dp, &
        5.9114839698395635746e-2_dp, 5.7277292100403215705e-2_dp, &
        5.5199503699984162868e-2_dp, 5.2890189485193667096e-2_dp, &
        5.0359035553854474958e-2_dp, 4.7616658492490474826e-2_dp, &
        4.4674560856694280419e-2_dp, 4.1545082943464749214e-2_dp, &
        3.8241351065830706317e-2_dp, 3.4777222564770438893e-2_dp, &
        3.1167227832798088902e-2_dp, 2.7426509708356948200e-2_dp, &
        2.3570760839324379141e-2_dp, 1.9616160457355527814e-2_dp, &
        1.5579315722943848728e-2_dp, 1.1477234579234539490e-2_dp, &
        7.3275539012762621024e-3_dp, 3.1533460523058386327e-3_dp]
    !> Most integrator steps over one segment of the monodromy (the paper's scenes take at
    !! most 640 at rtol 1e-10): a hopeless point (a body turning fast about a principal axis
    !! of tiny inertia) fails in about a second instead of running for minutes.
    integer, parameter, public :: FLOQUET_MAX_STEPS = 20000
    !> The forward sensitivities' absolute tolerance over the orbit's, rtol/100: their
    !! entries are measured against rtol itself (unit columns at the start: I or U0).
    real(dp), parameter :: H_ATOL_SCALE = 100.0_dp

    public :: check_torsion_scene, torsion_period, jacobian_z, monodromy, floquet_analysis
    public :: multipliers_from_monodromy, torsion_start, pencil_multipliers, floquet_point
    public :: point_values_valid, trivial_residual_of

    !> Sentinel written for chart points where no analysis is possible (not a torsion scene,
    !! cables cannot reach, impossible inertia): never NaN.
    real(dp), parameter, public :: CHART_INVALID = -1.0_dp
    !> Sentinel written for chart points whose analysis failed (e.g. more than
    !! FLOQUET_MAX_STEPS steps): never NaN.
    real(dp), parameter, public :: CHART_FAILED = -2.0_dp
    !> A rig symmetric to this (relative: l and l_prime; r cos(lambda) against b'/2) is
    !! symmetric: measured lengths agree no better, and pure torsion is then exact to
    !! second order in the difference.
    real(dp), parameter, public :: SYMMETRY_TOL = 1.0e-6_dp

contains

    !> Refuse a scene in which pure torsion is not an exact motion, saying which condition
    !! fails: equal cables, mass centre on the vertical bisector of AB (both to SYMMETRY_TOL),
    !! a principal axis vertical at rest.  Returns the index of the vertical principal axis.
    subroutine check_torsion_scene(p, ivert, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        integer, intent(out) :: ivert           !! which b_i is vertical at rest
        type(status_t), intent(out) :: stat     !! ERR_DECK naming the failed condition
        integer :: i
        character(len=200) :: buf
        ivert = 0
        if (abs(p%big_l - p%big_lp) > SYMMETRY_TOL*p%big_l) then
            write (buf, '(a,es12.5,a,es12.5,a)') '&suspension l/b'' = ', p%big_l, &
                ', l_prime/b'' = ', p%big_lp, ': pure torsion needs equal cables (l = l_prime)'
            call set_error(stat, ERR_DECK, trim(buf))
            return
        end if
        ! at rest R* - C = r (s_lam ntilde1 - c_lam ntilde3) with ntilde1 = -n3, ntilde3 = -n2:
        ! on the vertical through O when r cos(lambda) = b'/2
        if (abs(p%r*cos(p%lambda) - 0.5_dp) > SYMMETRY_TOL) then
            write (buf, '(a,es12.5,a)') '&body r cos(lambda) / b'' = ', p%r*cos(p%lambda), &
                ': the mass centre must lie on the vertical bisector of AB (r cos(lambda) = b''/2)'
            call set_error(stat, ERR_DECK, trim(buf))
            return
        end if
        ! b_i vertical at rest: row i of btilde is (+-1, 0, 0) (ntilde1 is vertical at rest)
        do i = 1, 3
            if (abs(abs(p%btilde(i, 1)) - 1.0_dp) < 1.0e-9_dp) ivert = i
        end do
        if (ivert == 0) then
            call set_error(stat, ERR_DECK, '&body btilde: no principal axis is vertical at '// &
                'rest (one row of btilde must be (+-1, 0, 0))')
        end if
    end subroutine check_torsion_scene

    !> Period t* (units of tau) of pure torsion with amplitude `amp` (rad).
    subroutine torsion_period(p, amp, ivert, period, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (a torsion scene)
        real(dp), intent(in) :: amp             !! amplitude of theta4 (rad), 0 < amp < pi
        integer, intent(in) :: ivert            !! vertical principal axis
        real(dp), intent(out) :: period         !! t*
        type(status_t), intent(out) :: stat     !! ERR_DECK when the cables cannot reach
        integer, parameter :: ng = size(GL_X)
        real(dp) :: phi, q, zs_q, zs_a, dz, dv, jq, s
        integer :: k
        period = 0.0_dp
        zs_a = p%big_l**2 - h2(amp)
        if (.not. (zs_a > 0.0_dp)) then
            call set_error(stat, ERR_DECK, '&floquet amplitude: the cables cannot reach '// &
                'the raised position at this amplitude; lower it or lengthen the cables')
            return
        end if
        zs_a = sqrt(zs_a)
        s = 0.0_dp
        do k = 1, ng
            phi = 0.25_dp*pi*(GL_X(k) + 1.0_dp)
            q = amp*sin(phi)
            zs_q = sqrt(p%big_l**2 - h2(q))
            ! z(A) - z(q) = (h2(A) - h2(q)) / (zs(q) + zs(A)), h2(A) - h2(q) = B/2 (cos q - cos A);
            ! dv is that over A^2 (each sine over A), so that a tiny A (1e-231 rad) does not
            ! underflow dv to 0: the integrand sqrt(jq/(2 (z(A) - z(q)))) A cos(phi)
            dv = p%big_b*(sin(0.5_dp*(amp + q))/amp)*(sin(0.5_dp*(amp - q))/amp)/(zs_q + zs_a)
            dz = 0.25_dp*p%big_b*sin(q)/zs_q
            jq = p%inertia(ivert) + dz**2
            s = s + GL_W(k)*sqrt(jq/(2.0_dp*dv))*cos(phi)
        end do
        period = 4.0_dp*0.25_dp*pi*s
    contains
        pure real(dp) function h2(qq)
            real(dp), intent(in) :: qq
            h2 = 0.25_dp + 0.25_dp*p%big_b**2 - 0.5_dp*p%big_b*cos(qq)
        end function h2
    end subroutine torsion_period

    !> Z = d f / d y of the chart right-hand side (eq. (51)), exact (bifilar_model's
    !! chart_jacobian: the derivatives of the kinematics through Kane's equations).
    subroutine jacobian_z(p, y, z, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp), intent(out) :: z(NSTATE, NSTATE)
        type(status_t), intent(out) :: stat
        real(dp) :: qdd(5)
        call chart_jacobian(p, y, qdd, z, stat)
    end subroutine jacobian_z

    !> Orbit and dH/dt = Z H together: y(1:10) the state, y(11:110) H by columns.
    subroutine variational_rhs(sys, t, y, ydot, stat)
        class(variational_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: z(NSTATE, NSTATE), a(5)
        integer :: c, i0, j
        call unused(t)
        call chart_jacobian(sys%p, y(1:NSTATE), a, z, stat)
        if (stat%code /= 0) return
        ydot(1:5) = y(6:10)
        ydot(6:10) = a
        ! column c of Z H: the upper half of Z is (0 I), so its first five rows are H's last
        do c = 1, NSTATE
            i0 = c*NSTATE
            ydot(i0 + 1:i0 + 5) = y(i0 + 6:i0 + 10)
            ydot(i0 + 6:i0 + 10) = 0.0_dp
            do j = 1, NSTATE
                ydot(i0 + 6:i0 + 10) = ydot(i0 + 6:i0 + 10) + z(6:10, j)*y(i0 + j)
            end do
        end do
    end subroutine variational_rhs

    !> The iteration matrix of the orbit + variational system for the BDF iteration:
    !! P = I - hl0 diag(Z, Z, ..., Z).  The coupling d(Z H)/dy_orbit = (dZ/dy) H is left out:
    !! the chord iteration needs only an approximate Jacobian, and this one costs a single Z.
    !! The eleven blocks are equal, so one 10 x 10 LU (LAPACK DGETRF) serves them all.
    subroutine variational_factor(sys, t, y, hl0, rewt, jnorm, singular, stat)
        class(variational_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:), hl0, rewt(:)
        real(dp), intent(out) :: jnorm
        logical, intent(out) :: singular
        type(status_t), intent(out) :: stat
        real(dp) :: z(NSTATE, NSTATE), rowsum
        type(status_t) :: lst
        integer :: c, i, j, i0
        call unused(t)
        jnorm = 0.0_dp
        singular = .false.
        call jacobian_z(sys%p, y(1:NSTATE), z, stat)
        if (stat%code /= 0) return
        ! the weighted max-row-sum norm of diag(Z, ..., Z): max_i w_i^-1 sum_j |J_ij| w_j
        do c = 0, NSTATE
            i0 = c*NSTATE
            do i = 1, NSTATE
                rowsum = 0.0_dp
                do j = 1, NSTATE
                    rowsum = rowsum + abs(z(i, j))/rewt(i0 + j)
                end do
                jnorm = max(jnorm, rowsum*rewt(i0 + i))
            end do
        end do
        sys%lu = -hl0*z
        do i = 1, NSTATE
            sys%lu(i, i) = sys%lu(i, i) + 1.0_dp
        end do
        call la_lu_factor(sys%lu, sys%ipiv, lst)
        singular = lst%code /= 0
    end subroutine variational_factor

    !> x := P^-1 x, block by block with the factors of variational_factor.
    subroutine variational_solve(sys, x, stat)
        class(variational_t), intent(inout) :: sys
        real(dp), intent(inout) :: x(:)
        type(status_t), intent(out) :: stat
        real(dp) :: xb(NSTATE, NSTATE + 1)
        xb = reshape(x, [NSTATE, NSTATE + 1])
        call la_lu_solve_many(sys%lu, sys%ipiv, xb, stat)
        x = reshape(xb, [NV])
    end subroutine variational_solve

    !> The variational system solves with its iteration matrix itself.
    logical function variational_structured(sys)
        class(variational_t), intent(in) :: sys
        call unused(sys)
        variational_structured = .true.
    end function variational_structured

    !> Monodromy H(t*) over one period from the chart state y0, as the product of `nseg`
    !! segment matrices (each integrated from H = I).  By default only half a period is
    !! integrated and the reversibility of the equations gives the other half (see below);
    !! `full = .true.` integrates the whole period.
    subroutine monodromy(p, y0, period, nseg, rtol, h, yend, nsteps, nrhs, stat, full, half, &
                         yhalf, method, sensitivities)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y0(NSTATE)      !! start of the orbit: a turning point, at rest
        real(dp), intent(in) :: period          !! t*
        integer, intent(in) :: nseg             !! shooting segments (>= 1)
        real(dp), intent(in) :: rtol            !! integrator tolerance
        real(dp), intent(out) :: h(NSTATE, NSTATE)  !! monodromy matrix
        real(dp), intent(out) :: yend(NSTATE)   !! state after one period (R y(t*/2) R-mirrored
                                                !! when the half period is used)
        integer, intent(out) :: nsteps, nrhs    !! integrator work
        type(status_t), intent(out) :: stat
        logical, intent(in), optional :: full   !! integrate the whole period (default: half)
        real(dp), intent(out), optional :: half(NSTATE, NSTATE)  !! H(t*/2) (half-period path)
        real(dp), intent(out), optional :: yhalf(NSTATE)         !! y(t*/2) (half-period path)
        integer, intent(in), optional :: method  !! SOLVER_LSODA (default) or SOLVER_RADAU
        !> SENS_FORWARD (default): H as the orbit's forward sensitivities; SENS_DIFFERENCES:
        !! the orbit and H as one system under the error control
        integer, intent(in), optional :: sensitivities
        type(variational_t) :: sys
        type(bifilar_t) :: orbit
        class(integrator_t), allocatable :: s
        type(integrator_stats_t) :: st
        real(dp) :: y(NV), eye(NSTATE, NSTATE), t0, t1, tend, lu(NSTATE, NSTATE), x(NSTATE)
        real(dp) :: rr(NSTATE), hinv(NSTATE, NSTATE), seg(NSTATE, NSTATE)
        integer :: k, j, ipiv(NSTATE)
        logical :: whole, forward
        whole = .false.
        if (present(full)) whole = full
        forward = .true.
        if (present(sensitivities)) forward = sensitivities /= SENS_DIFFERENCES
        if (present(method)) then
            call new_integrator(method, s)
        else
            call new_integrator(SOLVER_LSODA, s)
        end if
        tend = period
        if (.not. whole) tend = 0.5_dp*period
        sys%p = p
        orbit%p = p
        eye = 0.0_dp
        do j = 1, NSTATE
            eye(j, j) = 1.0_dp
        end do
        h = eye
        y(1:NSTATE) = y0
        nsteps = 0
        nrhs = 0
        do k = 1, nseg
            t0 = tend*(k - 1)/nseg
            t1 = tend*k/nseg
            if (forward) then
                ! the orbit with its sensitivities to its state at t0 (H = I there), in the
                ! error control: the orbit is smoother than the motions about it that H
                ! follows, and its steps alone leave H a hundred times less accurate; H's
                ! absolute tolerance is rtol (H_ATOL_SCALE)
                seg = eye
                call forward_segment(s, orbit, t0, t1, rtol, y(1:NSTATE), seg, nsteps, nrhs, &
                                     stat)
                if (stat%code /= 0) return
            else
                y(NSTATE + 1:NV) = reshape(eye, [NSTATE*NSTATE])
                call s%init(sys, t0, y, rtol, [rtol*1.0e-2_dp], stat, tcrit=t1, &
                            max_steps=FLOQUET_MAX_STEPS)
                if (stat%code /= 0) return
                call s%integrate(sys, t1, y, stat)
                st = s%stats()
                nsteps = nsteps + st%steps
                nrhs = nrhs + st%rhs_evals
                if (stat%code /= 0) return
                seg = reshape(y(NSTATE + 1:NV), [NSTATE, NSTATE])
            end if
            h = matmul(seg, h)
        end do
        yend = y(1:NSTATE)
        if (whole) return
        if (present(half)) half = h
        if (present(yhalf)) yhalf = y(1:NSTATE)
        ! reversibility: the accelerations are even in the rates, so R Phi_t R = Phi_-t with
        ! R = diag(I, -I); y0 and y(t*/2) are turning points at rest (R y = y), hence
        ! H(t*) = R H(t*/2)^-1 R H(t*/2)
        rr = [(1.0_dp, j=1, 5), (-1.0_dp, j=1, 5)]
        lu = h
        call la_lu_factor(lu, ipiv, stat)
        if (stat%code /= 0) return
        do j = 1, NSTATE
            x = 0.0_dp
            x(j) = 1.0_dp
            call la_lu_solve(lu, ipiv, x, stat)
            if (stat%code /= 0) return
            hinv(:, j) = x
        end do
        do j = 1, NSTATE
            hinv(j, :) = rr(j)*hinv(j, :)*rr
        end do
        h = matmul(hinv, h)
        ! by the same symmetry the orbit closes exactly when y(t*/2) is at rest: its rates are
        ! the closure error (reported through yend - y0)
        yend = y0 + [(0.0_dp, j=1, 5), y(NSTATE/2 + 1:NSTATE)]
    end subroutine monodromy

    !> The orbit's forward sensitivities to its start along the columns s0 over half a
    !! period: x = N s0, N = H(t*/2), with y(t*/2), in `nseg` segments (the columns carried
    !! from one segment to the next; each segment at most FLOQUET_MAX_STEPS steps).  The
    !! columns are in the integrator's error control (see monodromy), with absolute tolerance
    !! rtol (H_ATOL_SCALE).
    subroutine half_period_columns(p, y0, period, nseg, rtol, s0, x, yh, nsteps, nrhs, stat, &
                                   method)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y0(NSTATE)      !! start of the orbit: a turning point, at rest
        real(dp), intent(in) :: period          !! t*
        integer, intent(in) :: nseg             !! shooting segments (>= 1)
        real(dp), intent(in) :: rtol            !! integrator tolerance
        real(dp), intent(in) :: s0(:, :)        !! (NSTATE, m) the columns at t = 0
        real(dp), intent(out) :: x(:, :)        !! (NSTATE, m) N s0
        real(dp), intent(out) :: yh(NSTATE)     !! y(t*/2)
        integer, intent(out) :: nsteps, nrhs    !! integrator work
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: method  !! SOLVER_LSODA (default) or SOLVER_RADAU
        type(bifilar_t) :: orbit
        class(integrator_t), allocatable :: s
        real(dp) :: t0, t1, tend
        integer :: k
        if (present(method)) then
            call new_integrator(method, s)
        else
            call new_integrator(SOLVER_LSODA, s)
        end if
        tend = 0.5_dp*period
        orbit%p = p
        yh = y0
        x = s0
        nsteps = 0
        nrhs = 0
        do k = 1, nseg
            t0 = tend*(k - 1)/nseg
            t1 = tend*k/nseg
            call forward_segment(s, orbit, t0, t1, rtol, yh, x, nsteps, nrhs, stat)
            if (stat%code /= 0) return
        end do
    end subroutine half_period_columns

    !> One segment of the orbit from t0 to t1 with its forward sensitivities x (in: at t0,
    !! out: at t1) in the integrator's error control, their absolute tolerance rtol
    !! (H_ATOL_SCALE over the orbit's rtol/100); y the orbit's state (in: at t0, out: at
    !! t1); the segment's steps and right-hand sides added to nsteps, nrhs (also when it
    !! fails; at most FLOQUET_MAX_STEPS steps).
    subroutine forward_segment(s, orbit, t0, t1, rtol, y, x, nsteps, nrhs, stat)
        class(integrator_t), intent(inout) :: s
        type(bifilar_t), intent(inout) :: orbit
        real(dp), intent(in) :: t0, t1, rtol
        real(dp), intent(inout) :: y(NSTATE)
        real(dp), intent(inout) :: x(:, :)      !! (NSTATE, m)
        integer, intent(inout) :: nsteps, nrhs
        type(status_t), intent(out) :: stat
        type(integrator_stats_t) :: st
        integer :: j
        call s%init(orbit, t0, y, rtol, [rtol*1.0e-2_dp], stat, tcrit=t1, &
                    max_steps=FLOQUET_MAX_STEPS)
        if (stat%code /= 0) return
        call s%sens_init(orbit, x, stat, error_control=.true., &
                         scale=[(H_ATOL_SCALE, j = 1, size(x, 2))])
        if (stat%code /= 0) return
        call s%integrate(orbit, t1, y, stat)
        st = s%stats()
        nsteps = nsteps + st%steps
        nrhs = nrhs + st%rhs_evals
        if (stat%code /= 0) return
        call s%sens_dense(t1, 0, x, stat)
    end subroutine forward_segment

    !> The whole analysis at torsion amplitude `amp` (rad).
    !!
    !! The 10 x 10 monodromy H of the chart form has four multipliers that are 1 by structure,
    !! in two Jordan blocks: the time shift (eigenvector f(y0)) with the energy, and the
    !! constraint with its rate.  A Jordan block spreads its computed eigenvalues by the square
    !! root of the integration error, so the six others are taken from H reduced to the
    !! subspace S = {dG = dG' = dE = 0, orthogonal to f(y0)} (U0 an orthonormal basis of it,
    !! see reversible_multipliers).  They need the half-period map N = H(t*/2) only on S, as
    !! N U0: by default (forward sensitivities) only these six columns are integrated, the
    !! orbit's sensitivities to its start along U0.  With `whole_map` (or sensitivities =
    !! SENS_DIFFERENCES, whose variational system holds all of it) the whole N is integrated
    !! (monodromy) and N U0 taken from it; res%monodromy is then H(t*).
    !!
    !! The four trivial multipliers are reported as 1.  Their exact identities
    !! grad(G)^T N = grad(G)^T + t*/2 grad(G')^T, grad(G')^T N = grad(G')^T and
    !! grad(E)^T N = grad(E)^T on the constraint's tangent space (gradients at t*/2 on the
    !! left, at 0 on the right), on the computed columns: grad(X)(y(t*/2))^T N U0 = 0 for
    !! X = G, G', E, the map stays on the subspace the reduction assumes.  The largest
    !! residual, each relative to its gradient and to max(1, |N U0|_F), is
    !! res%trivial_residual.
    subroutine floquet_analysis(p_in, amp, rtol, nseg, res, stat, method, sensitivities, &
                                whole_map)
        type(pendulum_t), intent(in) :: p_in    !! scaled parameters (a torsion scene)
        real(dp), intent(in) :: amp             !! amplitude of theta4 (rad)
        real(dp), intent(in) :: rtol            !! integrator tolerance
        integer, intent(in) :: nseg             !! shooting segments
        type(floquet_result_t), intent(out) :: res
        !> ERR_DECK (scene), ERR_NUMERIC, ERR_MODEL (cable BC near the horizontal)
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: method !! SOLVER_LSODA (default) or SOLVER_RADAU
        integer, intent(in), optional :: sensitivities  !! SENS_FORWARD (default) or
                                                        !! SENS_DIFFERENCES (monodromy)
        !> .true.: the whole 10 x 10 half-period map (forward sensitivities of all ten
        !! columns), H(t*) in res%monodromy (default .false.: the six columns N U0)
        logical, intent(in), optional :: whole_map
        type(pendulum_t) :: p
        real(dp) :: y0(NSTATE), yend(NSTATE), h(NSTATE, NSTATE), hh(NSTATE, NSTATE)
        real(dp) :: yh(NSTATE), r0w(NSTATE, 3), f0(NSTATE), u0(NSTATE, 6), nu(NSTATE, 6)
        integer :: ivert
        logical :: whole
        p = p_in
        p%stab_rate = 0.0_dp      ! the variational equations of the model itself
        call check_torsion_scene(p, ivert, stat)
        if (stat%code /= 0) return
        call torsion_period(p, amp, ivert, res%period, stat)
        if (stat%code /= 0) return
        call torsion_start(p, amp, y0, stat)
        if (stat%code /= 0) return
        ! the cable swings out most at the turning point: beyond the model there (exit 4)
        if (.not. (y0(2)**2 + y0(3)**2 < SIN2_LIMIT**2)) then
            call set_error(stat, ERR_MODEL, 'at the amplitude cable BC is up at '// &
                'the horizontal (sin theta2 = '//sci(sqrt(y0(2)**2 + y0(3)**2), 6)//', '// &
                'beyond '//sci(SIN2_LIMIT, 4)//'): the model of a hanging cable no longer '// &
                'holds; lower the amplitude or lengthen the cables')
            return
        end if
        ! S at the start: the complement of grad G, grad G', grad E and the flow
        call structure_rows(p, y0, r0w, f0, stat)
        if (stat%code /= 0) return
        call complement_basis(reshape([r0w(:, 1), r0w(:, 2), r0w(:, 3), f0], [NSTATE, 4]), u0)
        whole = .false.
        if (present(whole_map)) whole = whole_map
        if (present(sensitivities)) whole = whole .or. sensitivities == SENS_DIFFERENCES
        if (whole) then
            call monodromy(p, y0, res%period, nseg, rtol, h, yend, res%steps, &
                           res%rhs_evaluations, stat, half=hh, yhalf=yh, method=method, &
                           sensitivities=sensitivities)
            if (stat%code /= 0) return
            nu = matmul(hh, u0)
            res%monodromy = h
        else
            call half_period_columns(p, y0, res%period, nseg, rtol, u0, nu, yh, res%steps, &
                                     res%rhs_evaluations, stat, method)
            if (stat%code /= 0) return
        end if
        ! by reversibility the orbit closes exactly when y(t*/2) is at rest (see monodromy):
        ! its rates are the closure error
        res%orbit_closure = maxval(abs(yh(6:10)))
        call reversible_multipliers(p, u0, yh, nu, res, stat)
    end subroutine floquet_analysis

    !> The chart state of pure torsion at its turning point theta4 = amp (at rest): the
    !! paper's raised pose (raised_angles) with theta_5 from the constraint eq. (2).  In a
    !! torsion scene the raised pose, CD horizontal (theta_5 = 0), satisfies eq. (2) up to
    !! l' - l (at most SYMMETRY_TOL l): Newton's method on G(theta_5) from 0 converges at
    !! once.  Only where it does not is the homotopy of start_pose's solve_theta5 used.
    subroutine torsion_start(p, amp, y0, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (a torsion scene)
        real(dp), intent(in) :: amp             !! amplitude (rad)
        real(dp), intent(out) :: y0(NSTATE)
        type(status_t), intent(out) :: stat
        real(dp) :: th(5), g, dg, b(5)
        integer :: it
        logical :: solved
        y0 = 0.0_dp
        call raised_angles(p, amp, th, stat)
        if (stat%code /= 0) return
        solved = .false.
        do it = 1, 8
            g = constraint_g(p, th)
            b = beta_coeffs(p, th)
            dg = -2.0_dp*b(5)                   ! dG/dtheta_5, eq. (4)
            if (.not. (abs(dg) > 1.0e-12_dp)) exit
            th(5) = th(5) - g/dg
            if (abs(g) < 1.0e-15_dp) then
                solved = abs(th(5)) < 0.5_dp*pi
                exit
            end if
        end do
        if (solved) solved = abs(constraint_g(p, th)) < 1.0e-12_dp
        if (.not. solved) then
            th(5) = 0.0_dp
            call solve_theta5(p, th, stat)
            if (stat%code /= 0) return
        end if
        y0 = chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp])
    end subroutine torsion_start

    !> Eigenvalues of R0 N^-1 Rh N (R0, Rh involutions) as the generalized eigenvalues of the
    !! pencil (Rh N, N R0) by QZ, sorted by decreasing modulus; never forms N^-1 or the product.
    subroutine pencil_multipliers(n, r0, rh, lam, stat)
        real(dp), intent(in) :: n(:, :)         !! half-period map (m x m)
        real(dp), intent(in) :: r0(:, :), rh(:, :)  !! the reversing involutions at both ends
        complex(dp), intent(out) :: lam(:)      !! the m multipliers
        type(status_t), intent(out) :: stat     !! ERR_NUMERIC: QZ failed or infinite multiplier
        complex(dp) :: alpha(size(n, 1))
        real(dp) :: beta(size(n, 1))
        lam = (0.0_dp, 0.0_dp)
        call la_geig(matmul(rh, n), matmul(n, r0), alpha, beta, stat)
        if (stat%code /= 0) return
        if (any(beta == 0.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'floquet: singular half-period map (infinite '// &
                           'multiplier); the orbit is not a clean torsion of this scene')
            return
        end if
        lam = alpha/beta
        lam = lam(by_modulus(lam))
    end subroutine pencil_multipliers

    !> The six non-trivial multipliers from the half-period map on S, N U0, without forming
    !! the product: with R = diag(I, -I), H(t*) = R N^-1 R N; reduced to S (as in
    !! multipliers_from_monodromy) at both turning points y0 and y(t*/2), both at rest and so
    !! R-invariant, M6 = R0 N6^-1 Rh N6 with N6 = Uh^T P N U0 (Uh the basis of S at t*/2, P
    !! the projection along the flow there), whose eigenvalues are those of the pencil
    !! (Rh N6, N6 R0), computed by QZ (LAPACK DGGEV).  The pencil is exchanged with its
    !! R-conjugate by lambda -> 1/lambda, so small and large multipliers are computed alike:
    !! the reciprocal partner of a multiplier of modulus 1e6 keeps its accuracy, where the
    !! eigenvalues of the explicit product lose it.  Fills res%multipliers (the four trivial
    !! ones 1), trivial, max_modulus, stable and trivial_residual (see floquet_analysis).
    subroutine reversible_multipliers(p, u0, yh, nu, res, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (stab_rate 0)
        real(dp), intent(in) :: u0(NSTATE, 6)   !! orthonormal basis of S at y(0)
        real(dp), intent(in) :: yh(NSTATE)      !! turning point at t*/2
        real(dp), intent(in) :: nu(NSTATE, 6)   !! N U0, N = H(t*/2)
        type(floquet_result_t), intent(inout) :: res
        type(status_t), intent(out) :: stat
        real(dp) :: rhw(NSTATE, 3), fh(NSTATE)
        real(dp) :: uh(NSTATE, 6), rr(NSTATE)
        real(dp) :: n6(6, 6), r0(6, 6), rh(6, 6)
        complex(dp) :: lam(6)
        integer :: k
        call structure_rows(p, yh, rhw, fh, stat)
        if (stat%code /= 0) return
        call complement_basis(reshape([rhw(:, 1), rhw(:, 2), rhw(:, 3), fh], [NSTATE, 4]), uh)
        res%trivial_residual = trivial_residual_of(rhw, nu)
        n6 = matmul(transpose(uh), matmul(projector_along(fh), nu))
        rr = [(1.0_dp, k=1, 5), (-1.0_dp, k=1, 5)]
        r0 = matmul(transpose(u0), spread(rr, 2, 6)*u0)
        rh = matmul(transpose(uh), spread(rr, 2, 6)*uh)
        call pencil_multipliers(n6, r0, rh, lam, stat)
        if (stat%code /= 0) return
        res%multipliers(1:6) = lam
        res%trivial(1:6) = .false.
        res%multipliers(7:10) = (1.0_dp, 0.0_dp)
        res%trivial(7:10) = .true.
        res%max_modulus = maxval(abs(res%multipliers(1:6)))
        res%stable = res%max_modulus <= 1.0_dp + STABILITY_MARGIN
    end subroutine reversible_multipliers

    !> The trivial identities on computed columns of the half-period map: the largest of
    !! |grad(X)^T N U0| / |grad(X)| over X = G, G', E (gradients at t*/2, the rows of
    !! structure_rows), over max(1, |N U0|_F).  Each is exactly 0 (see floquet_analysis).
    pure real(dp) function trivial_residual_of(rows, nu) result(r)
        real(dp), intent(in) :: rows(:, :)      !! (n, 3) grad G, grad G', grad E at t*/2
        real(dp), intent(in) :: nu(:, :)        !! (n, m) N U0
        integer :: i
        r = 0.0_dp
        do i = 1, size(rows, 2)
            r = max(r, norm2(matmul(rows(:, i), nu))/norm2(rows(:, i)))
        end do
        r = r/max(1.0_dp, norm2(nu))
    end function trivial_residual_of

    !> The multipliers of a whole monodromy matrix h of the chart form over the orbit
    !! through y0 with period t* (e.g. one from differences of the nonlinear flow): the six
    !! non-trivial ones the eigenvalues of h reduced to S, M6 = U^T P h U (U an orthonormal
    !! basis of S at y0, P the projection along f(y0); see floquet_analysis), the four
    !! trivial ones 1 and checked through their identities on the whole of h: h f = f,
    !! grad(E)^T h = grad(E)^T on the constraint's tangent space, grad(G')^T h = grad(G')^T,
    !! grad(G)^T h = grad(G)^T + t* grad(G')^T (largest residual, relative to the vector and
    !! to max(1, |h|_F)).  Fills res%multipliers, trivial, max_modulus, stable,
    !! trivial_residual and monodromy.
    subroutine multipliers_from_monodromy(p, y0, period, h, res, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (stab_rate 0)
        real(dp), intent(in) :: y0(NSTATE)      !! point of the orbit where h starts
        real(dp), intent(in) :: period          !! t*
        real(dp), intent(in) :: h(NSTATE, NSTATE)  !! monodromy matrix
        type(floquet_result_t), intent(inout) :: res
        type(status_t), intent(out) :: stat
        real(dp) :: rows(NSTATE, 4), u(NSTATE, 6), v(NSTATE, 8), m6(6, 6)
        real(dp) :: f(NSTATE), r, hn
        complex(dp) :: lam(6)
        call structure_rows(p, y0, rows, f, stat)
        if (stat%code /= 0) return
        ! residuals of the four exact identities, each relative to its vector
        ! (energy is conserved on the constraint manifold: its identity holds on its tangent
        !  space T = {dG = dG' = 0}, basis v)
        call complement_basis(rows(:, 1:2), v)
        hn = max(1.0_dp, norm2(h))
        r = norm2(matmul(h, f) - f)/norm2(f)
        r = max(r, norm2(matmul(matmul(rows(:, 3), h) - rows(:, 3), v))/norm2(rows(:, 3)))
        r = max(r, norm2(matmul(rows(:, 2), h) - rows(:, 2))/norm2(rows(:, 2)))
        r = max(r, norm2(matmul(rows(:, 1), h) - rows(:, 1) - period*rows(:, 2)) &
                /norm2(rows(:, 1)))
        res%trivial_residual = r/hn
        ! reduced map on S
        call complement_basis(reshape([rows(:, 1), rows(:, 2), rows(:, 3), f], [NSTATE, 4]), u)
        m6 = matmul(transpose(u), matmul(projector_along(f), matmul(h, u)))
        call la_eig(m6, lam, stat)
        if (stat%code /= 0) return
        res%multipliers(1:6) = lam(by_modulus(lam))
        res%trivial(1:6) = .false.
        res%multipliers(7:10) = (1.0_dp, 0.0_dp)
        res%trivial(7:10) = .true.
        res%max_modulus = maxval(abs(res%multipliers(1:6)))
        res%stable = res%max_modulus <= 1.0_dp + STABILITY_MARGIN
        res%monodromy = h
    end subroutine multipliers_from_monodromy

    !> Indices that order lam by decreasing modulus (insertion sort), of equal moduli (a
    !! complex conjugate pair) the larger imaginary part first; other ties keep their order.
    pure function by_modulus(lam) result(idx)
        complex(dp), intent(in) :: lam(:)
        integer :: idx(size(lam))
        integer :: k, i
        idx = [(k, k=1, size(lam))]
        do k = 2, size(lam)
            i = k
            do while (i > 1)
                if (abs(lam(idx(i))) < abs(lam(idx(i - 1)))) exit
                if (abs(lam(idx(i))) == abs(lam(idx(i - 1))) .and. &
                    aimag(lam(idx(i))) <= aimag(lam(idx(i - 1)))) exit
                idx([i - 1, i]) = idx([i, i - 1])
                i = i - 1
            end do
        end do
    end function by_modulus

    !> The projection I - f f^T/|f|^2 along the flow direction f.
    pure function projector_along(f) result(pf)
        real(dp), intent(in) :: f(NSTATE)
        real(dp) :: pf(NSTATE, NSTATE)
        integer :: k
        pf = -spread(f, 2, NSTATE)*spread(f, 1, NSTATE)/dot_product(f, f)
        do k = 1, NSTATE
            pf(k, k) = pf(k, k) + 1.0_dp
        end do
    end function projector_along

    !> Gradients at y of the constraint G, its rate G' and the energy E (columns 1-3, exact:
    !! bifilar_model's chart_invariant_gradients), and the flow f(y).  A state whose cable BC
    !! is near the horizontal (|sin theta2| > SIN2_LIMIT) is ERR_MODEL.
    subroutine structure_rows(p, y, rows, f, stat)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(NSTATE)
        real(dp), intent(out) :: rows(NSTATE, 3), f(NSTATE)
        type(status_t), intent(out) :: stat
        real(dp) :: a(5)
        rows = 0.0_dp
        f = 0.0_dp
        if (.not. (y(2)**2 + y(3)**2 < SIN2_LIMIT**2)) then
            call set_error(stat, ERR_MODEL, 'cable BC swings up to the horizontal '// &
                'in the torsion (sin theta2 = '//sci(sqrt(y(2)**2 + y(3)**2), 6)//'): the '// &
                'model of a hanging cable no longer holds; lower the amplitude or lengthen '// &
                'the cables')
            return
        end if
        call chart_invariant_gradients(p, y, rows)
        call chart_accelerations(p, y, a, stat)
        f = [y(6:10), a]
    end subroutine structure_rows

    !> Orthonormal basis u (n x (n-m)) of the orthogonal complement of the columns of a
    !! (n x m, independent, non-zero), by modified Gram-Schmidt applied twice.
    pure subroutine complement_basis(a, u)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(out) :: u(:, :)
        real(dp) :: q(size(a, 1), size(a, 1)), v(size(a, 1))
        integer :: n, m, k, j, nq, pass
        n = size(a, 1)
        m = size(a, 2)
        nq = 0
        do k = 1, n + m
            if (k <= m) then
                v = a(:, k)/norm2(a(:, k))     ! scale-free: the columns may be tiny
            else
                v = 0.0_dp
                v(k - m) = 1.0_dp
            end if
            do pass = 1, 2
                do j = 1, nq
                    v = v - dot_product(q(:, j), v)*q(:, j)
                end do
            end do
            ! the given columns are always kept (near equilibrium grad E is almost parallel to
            ! grad G, leaving a remainder of the order of the amplitude); the unit vectors
            ! that complete the basis only when well independent
            if ((k <= m .and. norm2(v) > 1.0e-12_dp) .or. (norm2(v) > 1.0e-3_dp .and. nq < n)) then
                nq = nq + 1
                q(:, nq) = v/norm2(v)
            end if
        end do
        u = q(:, m + 1:n)
    end subroutine complement_basis

    !> One point of a stability sweep (chart, design): the largest multiplier and the period
    !! of pure torsion of p at amp_deg, or a sentinel in both: CHART_INVALID where no
    !! analysis is possible (impossible inertia, not a torsion scene, the cables cannot reach
    !! the raised position), CHART_FAILED where the analysis failed (e.g. more than
    !! FLOQUET_MAX_STEPS steps).  Never stops, never NaN.
    subroutine floquet_point(p, amp_deg, rtol, nseg, modulus, period, method, sensitivities)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: amp_deg         !! torsion amplitude (degrees)
        real(dp), intent(in) :: rtol            !! integrator tolerance
        integer, intent(in) :: nseg             !! shooting segments
        real(dp), intent(out) :: modulus        !! largest |multiplier| (or a sentinel)
        real(dp), intent(out) :: period         !! t* in units of tau (or a sentinel)
        integer, intent(in), optional :: method !! SOLVER_LSODA (default) or SOLVER_RADAU
        integer, intent(in), optional :: sensitivities  !! SENS_FORWARD (default) or
                                                        !! SENS_DIFFERENCES (monodromy)
        type(floquet_result_t) :: res
        type(status_t) :: st
        integer :: ivert
        logical :: valid
        modulus = CHART_INVALID
        period = CHART_INVALID
        valid = all(p%inertia > 0.0_dp) .and. p%inertia(1) <= p%inertia(2) + p%inertia(3) &
                .and. p%inertia(2) <= p%inertia(1) + p%inertia(3) &
                .and. p%inertia(3) <= p%inertia(1) + p%inertia(2)
        if (.not. valid) return
        call check_torsion_scene(p, ivert, st)
        if (st%code /= 0) return
        call floquet_analysis(p, amp_deg*deg, rtol, nseg, res, st, method, sensitivities)
        if (st%code == 0) then
            modulus = res%max_modulus
            period = res%period
        else if (st%code /= ERR_DECK .and. st%code /= ERR_MODEL) then
            ! (ERR_DECK, ERR_MODEL: no torsion at this amplitude, CHART_INVALID)
            modulus = CHART_FAILED
            period = CHART_FAILED
        end if
    end subroutine floquet_point

    !> Whether values could come from floquet_point (values of a chart or a design read back
    !! from a checkpoint): a finite modulus >= 0 with a finite period > 0, or a sentinel
    !! (CHART_INVALID, CHART_FAILED) in both; without a period, the modulus alone.  (No
    !! operation on a value before it is known finite: a signalling NaN traps.)
    pure logical function point_values_valid(modulus, period) result(ok)
        real(dp), intent(in) :: modulus                 !! largest |multiplier| or a sentinel
        real(dp), intent(in), optional :: period        !! the period or the same sentinel
        ok = .false.
        if (.not. finite_bits(modulus)) return
        if (present(period)) then
            if (.not. finite_bits(period)) return
        end if
        if (modulus == CHART_INVALID .or. modulus == CHART_FAILED) then
            ok = .true.
            if (present(period)) ok = period == modulus
            return
        end if
        ok = modulus >= 0.0_dp
        if (ok .and. present(period)) ok = period > 0.0_dp
    end function point_values_valid

end module floquet
