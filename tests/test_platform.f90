!> Tests of the multifilar platform (modules platform_geometry, platform_model,
!! platform_elastic, platform_run): the kinematics against finite differences and Kane's
!! equations against an independent Newton-Euler model (tests/platform_reference.f90); two
!! cables against the paper's model; pure torsion against the paper's reduced equation;
!! small-amplitude frequencies against the linearised model of doc/theory.md; energy over
!! 100 periods; the elastic model's convergence to the inextensible one and to the paper's
!! as 1/k; a test-mass series against the independent model, and fitted by identify's
!! period inversion on the platform (module platform_measure); the rest pose, the tipping
!! height and the refusals; slack.
module test_platform
    use kinds, only: dp, pi, deg
    use status, only: status_t, ERR_MODEL
    use testing, only: tester_t
    use text, only: sci
    use vectors, only: cross
    use ode_system, only: ode_system_t, integrator_t, integrator_stats_t
    use integrators, only: new_integrator, SOLVER_LSODA, SOLVER_RADAU
    use run_loop, only: drive, row_sink_t, stepped_model_t
    use geometry, only: pendulum_t
    use gen_forces, only: inertia_dyadic
    use start_pose, only: raised_angles, solve_theta5
    use bifilar_model, only: bifilar_t, motion_t, chart_state, evaluate, chart_positions, NSTATE
    use floquet, only: torsion_period, torsion_start
    use platform_geometry, only: platform_t, platform_kin_t, regular_platform, &
                                 general_platform, platform_prepare, solve_pose, &
                                 master_residual, rotation, QPSI
    use platform_model, only: platform_sys_t, platform_motion_t, platform_modes_t, &
                              check_platform, platform_evaluate, platform_start, linearise, &
                              tipping_depth, pose_of_state, platform_energy, rest_pose
    use platform_elastic, only: platform_elastic_t, pe_motion_t, pe_from_inextensible, &
                                pe_evaluate, pe_energy, pe_rest_pose, pe_start, pe_linearise, &
                                pe_pose
    use platform_run, only: platform_run_t, platform_run_start, elastic_run_start
    use lapack_wrap, only: la_solve
    use platform_reference, only: ref_body_t, ref_rotation, ref_constraints, ref_energy, &
                                  ref_tensions, ref_quat_of_yaw_tilt, REF_NSTATE
    use unused_arg, only: unused
    use rig, only: rig_t, accuracy_t
    use budget, only: input_u_t
    use period_inversion, only: invert_periods, period_fit_t
    use test_platform_analyses, only: run_platform_analysis_tests
    use test_platform_records, only: run_platform_record_tests
    implicit none
    private

    public :: run_platform_tests

    real(dp), parameter :: GRAV = 9.81_dp
    real(dp), parameter :: MASS = 1.3_dp

    !> A sink that keeps the states it is given (run_loop).
    type, extends(row_sink_t) :: keep_t
        real(dp), allocatable :: y(:, :)
    contains
        procedure :: take => keep_take
    end type keep_t

contains

    subroutine run_platform_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('platform: kinematics against finite differences, Kane against '// &
                   'Newton-Euler')) call test_kinematics(t)
        if (t%want('platform: two cables against the paper''s model')) call test_bifilar(t)
        if (t%want('platform: pure torsion against the paper''s reduced equation')) &
            call test_torsion(t)
        if (t%want('platform: small-amplitude frequencies against the linearised model')) &
            call test_frequencies(t)
        if (t%want('platform: energy over 100 periods')) call test_energy(t)
        if (t%want('platform: elastic n = 3 converges to the inextensible model as 1/k')) &
            call test_elastic_limit(t)
        if (t%want('platform: elastic n = 2 converges to the paper''s model as 1/k')) &
            call test_elastic_bifilar(t)
        if (t%want('platform: test-mass series against an independent model')) &
            call test_mass_series(t)
        if (t%want('platform: test-mass series fitted by identify on the platform')) &
            call test_mass_identify(t)
        if (t%want('platform: rest pose, tipping height, bad platforms')) call test_rest(t)
        if (t%want('platform: slack ends the inextensible model, not the elastic one')) &
            call test_slack(t)
        call run_platform_analysis_tests(t, exe)
        call run_platform_record_tests(t, exe)
    end subroutine run_platform_tests

    ! ---------------------------------------------------------------------------------------
    ! Helpers
    ! ---------------------------------------------------------------------------------------

    !> The body of most tests: m = 1.3, I = diag(0.05, 0.06, 0.09) about the mass centre.
    pure function body_inertia() result(jb)
        real(dp) :: jb(3, 3)
        jb = 0.0_dp
        jb(1, 1) = 0.05_dp
        jb(2, 2) = 0.06_dp
        jb(3, 3) = 0.09_dp
    end function body_inertia

    !> A regular platform of n cables with the body of body_inertia.
    function regular(n, r, rp, l, offset, depth) result(pl)
        integer, intent(in) :: n
        real(dp), intent(in) :: r, rp, l, offset(2), depth
        type(platform_t) :: pl
        pl = regular_platform(n, r, rp, l, MASS, body_inertia(), offset, depth, GRAV)
    end function regular

    !> The mean period of the oscillation of component comp of the state: the mean spacing of
    !! nper + 1 successive falls of y(comp) through 0, located on the dense output.
    subroutine measure_period(sys, y0, comp, nper, rtol, atol, method, tmax, per, ok)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: y0(:)
        integer, intent(in) :: comp, nper, method
        real(dp), intent(in) :: rtol, atol, tmax
        real(dp), intent(out) :: per
        logical, intent(out) :: ok
        class(integrator_t), allocatable :: it
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: y(size(y0)), yprev(size(y0)), ym(size(y0)), tprev, tnow, a, b, c, tc(nper + 1)
        integer :: ncross, k, j
        ok = .false.
        per = 0.0_dp
        call new_integrator(method, it)
        call it%init(sys, 0.0_dp, y0, rtol, [atol], stat, tcrit=tmax)
        if (stat%code /= 0) return
        yprev = y0
        tprev = 0.0_dp
        ncross = 0
        do k = 1, 2000000
            call it%step(sys, stat, tout=tmax)
            if (stat%code /= 0) return
            st = it%stats()
            tnow = st%t_current
            call it%dense(tnow, 0, y, stat)
            if (yprev(comp) > 0.0_dp .and. y(comp) <= 0.0_dp) then
                a = tprev
                b = tnow
                do j = 1, 200
                    c = 0.5_dp*(a + b)
                    if (.not. (c > a .and. c < b)) exit
                    call it%dense(c, 0, ym, stat)
                    if (ym(comp) > 0.0_dp) then
                        a = c
                    else
                        b = c
                    end if
                end do
                ncross = ncross + 1
                tc(ncross) = 0.5_dp*(a + b)
                if (ncross == nper + 1) exit
            end if
            if (tnow >= tmax) exit
            yprev = y
            tprev = tnow
        end do
        if (ncross < nper + 1) return
        per = (tc(nper + 1) - tc(1))/nper
        ok = .true.
    end subroutine measure_period

    !> Integrate sys from y0 to t1.
    subroutine integrate(sys, y0, t1, rtol, atol, method, y1, stat, steps)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: y0(:), t1, rtol, atol
        integer, intent(in) :: method
        real(dp), intent(out) :: y1(:)
        type(status_t), intent(out) :: stat
        integer, intent(out), optional :: steps
        class(integrator_t), allocatable :: it
        type(integrator_stats_t) :: st
        call new_integrator(method, it)
        call it%init(sys, 0.0_dp, y0, rtol, [atol], stat, tcrit=t1, max_steps=2000000)
        if (stat%code /= 0) return
        call it%integrate(sys, t1, y1, stat)
        st = it%stats()
        if (present(steps)) steps = st%steps
    end subroutine integrate

    subroutine keep_take(sink, m, k, t, y, stat)
        class(keep_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        type(status_t), intent(out) :: stat
        stat%code = 0
        if (.not. allocated(sink%y)) allocate (sink%y(size(y), 0:1000))
        if (k <= ubound(sink%y, 2)) sink%y(:, k) = y
        call unused(m)
        call unused(t)
    end subroutine keep_take

    !> The angles' rates (psi', theta', phi') of angular velocity w at pose q.
    pure function angle_rates(q, w) result(r)
        real(dp), intent(in) :: q(6), w(3)
        real(dp) :: r(3), a(3, 3), rot(3, 3), det, ai(3, 3)
        rot = rotation(q(4), q(5), q(6))
        a(:, 1) = [0.0_dp, 0.0_dp, 1.0_dp]
        a(:, 2) = [-sin(q(4)), cos(q(4)), 0.0_dp]
        a(:, 3) = rot(:, 1)
        ai(1, :) = cross(a(:, 2), a(:, 3))
        ai(2, :) = cross(a(:, 3), a(:, 1))
        ai(3, :) = cross(a(:, 1), a(:, 2))
        det = dot_product(a(:, 1), ai(1, :))
        r = matmul(ai, w)/det
    end function angle_rates

    !> Pose angles (psi, theta, phi) of a rotation matrix R = Rz Ry Rx.
    pure function angles_of(r) result(a)
        real(dp), intent(in) :: r(3, 3)
        real(dp) :: a(3)
        a = [atan2(r(2, 1), r(1, 1)), -asin(max(-1.0_dp, min(1.0_dp, r(3, 1)))), &
             atan2(r(3, 2), r(3, 3))]
    end function angles_of

    !> The reference model's state of a platform's motion mo.
    function to_reference(pl, mo) result(yr)
        type(platform_t), intent(in) :: pl
        type(platform_motion_t), intent(in) :: mo
        real(dp) :: yr(REF_NSTATE), r(3, 3)
        r = rotation(mo%q(4), mo%q(5), mo%q(6))
        yr(1:3) = mo%rc
        yr(4:6) = mo%vc
        yr(7:10) = quat_of(r)
        yr(11:13) = matmul(transpose(r), mo%omega)
        call unused(pl)
    end function to_reference

    !> The unit quaternion of a rotation matrix (Shepperd's choice of the largest term).
    pure function quat_of(r) result(q)
        real(dp), intent(in) :: r(3, 3)
        real(dp) :: q(4), tr
        tr = r(1, 1) + r(2, 2) + r(3, 3)
        if (tr > 0.0_dp) then
            q(1) = 0.5_dp*sqrt(1.0_dp + tr)
            q(2) = (r(3, 2) - r(2, 3))/(4.0_dp*q(1))
            q(3) = (r(1, 3) - r(3, 1))/(4.0_dp*q(1))
            q(4) = (r(2, 1) - r(1, 2))/(4.0_dp*q(1))
        else if (r(1, 1) >= r(2, 2) .and. r(1, 1) >= r(3, 3)) then
            q(2) = 0.5_dp*sqrt(1.0_dp + r(1, 1) - r(2, 2) - r(3, 3))
            q(1) = (r(3, 2) - r(2, 3))/(4.0_dp*q(2))
            q(3) = (r(1, 2) + r(2, 1))/(4.0_dp*q(2))
            q(4) = (r(1, 3) + r(3, 1))/(4.0_dp*q(2))
        else if (r(2, 2) >= r(3, 3)) then
            q(3) = 0.5_dp*sqrt(1.0_dp + r(2, 2) - r(1, 1) - r(3, 3))
            q(1) = (r(1, 3) - r(3, 1))/(4.0_dp*q(3))
            q(2) = (r(1, 2) + r(2, 1))/(4.0_dp*q(3))
            q(4) = (r(2, 3) + r(3, 2))/(4.0_dp*q(3))
        else
            q(4) = 0.5_dp*sqrt(1.0_dp + r(3, 3) - r(1, 1) - r(2, 2))
            q(1) = (r(2, 1) - r(1, 2))/(4.0_dp*q(4))
            q(2) = (r(1, 3) + r(3, 1))/(4.0_dp*q(4))
            q(3) = (r(2, 3) + r(3, 2))/(4.0_dp*q(4))
        end if
    end function quat_of

    !> The reference model of a platform's rig (its body points from the mass centre).
    function reference_of(pl) result(rb)
        type(platform_t), intent(in) :: pl
        type(ref_body_t) :: rb
        integer :: i
        rb%n = pl%n
        allocate (rb%s(3, pl%n), rb%b(3, pl%n), rb%l(pl%n))
        do i = 1, pl%n
            rb%s(:, i) = pl%support(:, i)
            rb%b(:, i) = pl%body(:, i) - pl%cg
            rb%l(i) = pl%length(i)
        end do
        rb%m = pl%mass
        rb%g = pl%gravity
        rb%j = pl%inertia
    end function reference_of

    ! ---------------------------------------------------------------------------------------
    !> The kinematics of platform_kinematics against finite differences of the solved pose
    !! along the state's rates (velocities, accelerations at Qddot = 0, angular velocity and
    !! acceleration), the constraints to roundoff; Kane's accelerations and tensions
    !! against the reference model's Newton-Euler with multipliers at the same state.
    subroutine test_kinematics(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_elastic_t) :: el
        type(platform_kin_t) :: k, kp, km
        type(platform_motion_t) :: mo
        type(status_t) :: st
        type(ref_body_t) :: rb
        real(dp) :: y(6), yp(6), ym(6), h, ye(12), yep(12), yem(12), qr(6)
        real(dp) :: yr(REF_NSTATE), fr(REF_NSTATE), tref(3), lm(3)
        real(dp) :: err_v, err_a, err_w, err_al, err_g
        ! n = 3, off the axis, R /= R'
        pl = regular(3, 0.5_dp, 0.4_dp, 1.2_dp, [0.05_dp, 0.02_dp], 0.1_dp)
        call check_platform(pl, st)
        call t%check('platform kinematics: the rig is accepted', st%code == 0)
        y = [0.01_dp, -0.02_dp, 0.6_dp, 0.1_dp, -0.2_dp, 0.7_dp]
        h = 1.0e-5_dp
        call pose_of_state(pl, y, k, st)
        yp = y
        yp(1:3) = y(1:3) + h*y(4:6)
        ym = y
        ym(1:3) = y(1:3) - h*y(4:6)
        call pose_of_state(pl, yp, kp, st)
        call pose_of_state(pl, ym, km, st)
        call fd_errors(k, kp, km, h, err_v, err_a, err_w, err_al)
        call t%check_close('platform kinematics n = 3: velocity of the origin', err_v, 0.0_dp, &
                           0.0_dp, 1.0e-8_dp)
        call t%check_close('platform kinematics n = 3: its acceleration at u'' = 0', err_a, &
                           0.0_dp, 0.0_dp, 1.0e-5_dp)
        call t%check_close('platform kinematics n = 3: angular velocity', err_w, 0.0_dp, &
                           0.0_dp, 1.0e-8_dp)
        call t%check_close('platform kinematics n = 3: angular acceleration at u'' = 0', &
                           err_al, 0.0_dp, 0.0_dp, 1.0e-7_dp)
        lm = pl%length(1:3)
        err_g = maxval(abs(master_residual(pl, k%q, lm)))
        call t%check_close('platform kinematics n = 3: constraints to roundoff', err_g, &
                           0.0_dp, 0.0_dp, 1.0e-14_dp)
        ! Kane against Newton-Euler with multipliers
        call platform_evaluate(pl, y, mo, st)
        rb = reference_of(pl)
        rb%beta = 0.0_dp
        yr = to_reference(pl, mo)
        call rb%rhs(0.0_dp, yr, fr, st)
        call t%check_close('platform: Kane''s mass-centre acceleration = Newton-Euler''s', &
                           maxval(abs(fr(4:6) - mo%ac)), 0.0_dp, 0.0_dp, 1.0e-12_dp)
        call t%check_close('platform: Kane''s angular acceleration = Newton-Euler''s', &
                           maxval(abs(matmul(rotation(mo%q(4), mo%q(5), mo%q(6)), &
                                             fr(11:13)) - mo%alpha)), 0.0_dp, 0.0_dp, &
                           1.0e-11_dp)
        call ref_tensions(rb, yr, tref, st)
        call t%check_close('platform: tensions from the multipliers = Newton-Euler''s', &
                           maxval(abs(tref - mo%tension)), 0.0_dp, 0.0_dp, 1.0e-11_dp)
        ! a turn of 150 degrees from the reference pose: Newton (or the homotopy) finds it
        block
            real(dp) :: q(6)
            q = pl%q_ref
            q(QPSI) = 150.0_dp*deg
            call solve_pose(pl, q, lm, st, from_ref=.true.)
            call t%check('platform: the pose of a 150 degree turn is solved', st%code == 0 &
                         .and. maxval(abs(master_residual(pl, q, lm))) < 1.0e-14_dp)
            ! the homotopy: Newton allowed one iteration, from the reference pose, fails;
            ! the homotopy then reaches the same pose
            block
                real(dp) :: qh(6)
                integer :: its
                qh = pl%q_ref
                qh(QPSI) = 150.0_dp*deg
                call solve_pose(pl, qh, lm, st, from_ref=.true., newton_limit=1, &
                                iterations=its)
                call t%check('platform: the homotopy finds the pose Newton finds', &
                             st%code == 0 .and. its > 100 .and. &
                             maxval(abs(qh - q)) < 1.0e-13_dp)
            end block
            ! from a guess above the supports Newton fails over to the reference pose
            q(3) = 5.0_dp
            q(5:6) = [1.2_dp, -1.3_dp]
            call solve_pose(pl, q, lm, st)
            call t%check('platform: a bad guess falls back to the reference pose', &
                         st%code == 0 .and. q(3) < 0.0_dp .and. &
                         maxval(abs(master_residual(pl, q, lm))) < 1.0e-14_dp)
        end block
        ! n = 2 (the rig of the paper's cylinder)
        pl = bifilar_platform(cylinder_pendulum(1.8_dp))
        call check_platform(pl, st)
        call t%check('platform kinematics n = 2: the rig is accepted', st%code == 0)
        block
            real(dp) :: y8(8), y8p(8), y8m(8)
            y8 = [pl%q_ref(pl%free(1:4)), 0.1_dp, -0.05_dp, 0.4_dp, 0.3_dp]
            y8(4) = y8(4) + 0.2_dp
            call pose_of_state(pl, y8, k, st)
            y8p = y8
            y8p(1:4) = y8(1:4) + h*y8(5:8)
            y8m = y8
            y8m(1:4) = y8(1:4) - h*y8(5:8)
            call pose_of_state(pl, y8p, kp, st)
            call pose_of_state(pl, y8m, km, st)
            call fd_errors(k, kp, km, h, err_v, err_a, err_w, err_al)
            call t%check('platform kinematics n = 2: velocities and accelerations', &
                         max(err_v, err_w) < 1.0e-8_dp .and. max(err_a, err_al) < 1.0e-5_dp)
            call platform_evaluate(pl, y8, mo, st)
            rb = reference_of(pl)
            rb%beta = 0.0_dp
            yr = to_reference(pl, mo)
            call rb%rhs(0.0_dp, yr, fr, st)
            call t%check_close('platform n = 2: Kane''s acceleration = Newton-Euler''s', &
                               maxval(abs(fr(4:6) - mo%ac)), 0.0_dp, 0.0_dp, 1.0e-12_dp)
        end block
        ! elastic n = 4: the stretches are coordinates too
        el%pl = regular(4, 0.5_dp, 0.4_dp, 1.2_dp, [0.03_dp, 0.0_dp], 0.1_dp)
        el%stiffness = 1.0e4_dp
        call platform_prepare(el%pl, st)
        call pe_rest_pose(el, qr, st)
        call t%check('platform kinematics elastic n = 4: a rest pose', st%code == 0)
        ye(1:6) = qr
        ye(1:3) = ye(1:3) + [0.01_dp, 0.0_dp, 0.3_dp]
        ye(7:12) = [0.1_dp, -0.2_dp, 0.5_dp, 1.0e-4_dp, -2.0e-4_dp, 3.0e-4_dp]
        call pe_pose(el, ye, k, st)
        yep = ye
        yep(1:6) = ye(1:6) + h*ye(7:12)
        yem = ye
        yem(1:6) = ye(1:6) - h*ye(7:12)
        call pe_pose(el, yep, kp, st)
        call pe_pose(el, yem, km, st)
        call fd_errors(k, kp, km, h, err_v, err_a, err_w, err_al)
        call t%check('platform kinematics elastic n = 4: velocities and accelerations', &
                     max(err_v, err_w) < 1.0e-8_dp .and. max(err_a, err_al) < 1.0e-5_dp)
    end subroutine test_kinematics

    !> Central differences of the pose along the rates against the kinematics at the centre.
    subroutine fd_errors(k, kp, km, h, ev, ea, ew, eal)
        type(platform_kin_t), intent(in) :: k, kp, km
        real(dp), intent(in) :: h
        real(dp), intent(out) :: ev, ea, ew, eal
        real(dp) :: wm(3, 3)
        ev = maxval(abs((kp%q(1:3) - km%q(1:3))/(2.0_dp*h) - k%vr))
        ea = maxval(abs((kp%q(1:3) - 2.0_dp*k%q(1:3) + km%q(1:3))/h**2 - k%a0))
        wm = matmul((kp%rot - km%rot)/(2.0_dp*h), transpose(k%rot))
        ew = maxval(abs([wm(3, 2), wm(1, 3), wm(2, 1)] - k%omega))
        eal = maxval(abs((kp%omega - km%omega)/(2.0_dp*h) - k%al0))
    end subroutine fd_errors

    ! ---------------------------------------------------------------------------------------
    !> The paper's cylinder (scaled: b' = m = g = 1), l' = lp.
    function cylinder_pendulum(lp) result(p)
        real(dp), intent(in) :: lp
        type(pendulum_t) :: p
        p = pendulum_t()
        p%big_lp = lp
    end function cylinder_pendulum

    !> The platform of a bifilar pendulum (scaled units): cable 1 = BC from B = (0, -B, 0) to
    !! C, cable 2 = AD from A = 0 to D; the body frame x = -ntilde3 (C to D), z = -ntilde1
    !! (up at rest), origin C.
    function bifilar_platform(p) result(pl)
        type(pendulum_t), intent(in) :: p
        type(platform_t) :: pl
        real(dp) :: sup(3, 2), bod(3, 2), jn(3, 3), tm(3, 3)
        sup(:, 1) = [0.0_dp, -p%big_b, 0.0_dp]
        sup(:, 2) = 0.0_dp
        bod(:, 1) = 0.0_dp
        bod(:, 2) = [1.0_dp, 0.0_dp, 0.0_dp]
        jn = inertia_dyadic(p%btilde, p%inertia)
        tm = reshape([0.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, &
                      0.0_dp], [3, 3])      ! rows: the body axes in ntilde components
        pl = general_platform(2, sup, bod, [p%big_l, p%big_lp], 1.0_dp, &
                              matmul(tm, matmul(jn, transpose(tm))), &
                              [p%r*cos(p%lambda), 0.0_dp], p%r*sin(p%lambda), 1.0_dp)
    end function bifilar_platform

    !> The platform state (n = 2) of a bifilar chart state.
    function platform_state_of(p, pl, yb) result(y)
        type(pendulum_t), intent(in) :: p
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: yb(NSTATE)
        real(dp) :: y(8), c(3), d(3), rs(3), e(3), n(3, 3), r(3, 3), q(6), qd(6), vc(3)
        type(motion_t) :: mo
        type(status_t) :: st
        call chart_positions(p, yb, c, d, rs, e, n)
        call evaluate(p, yb, 0.0_dp, mo, st)
        r(:, 1) = -n(3, :)
        r(:, 3) = -n(1, :)
        r(:, 2) = cross(r(:, 3), r(:, 1))
        q(1:3) = c
        q(4:6) = angles_of(r)
        vc = mo%vstar - cross(mo%omega, rs - c)
        qd(1:3) = vc
        qd(4:6) = angle_rates(q, mo%omega)
        y(1:4) = q(pl%free(1:4))
        y(5:8) = qd(pl%free(1:4))
    end function platform_state_of

    !> The mass centre of a bifilar chart state.
    function bifilar_rstar(p, yb) result(rs)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: yb(NSTATE)
        real(dp) :: rs(3), c(3), d(3), e(3), n(3, 3)
        call chart_positions(p, yb, c, d, rs, e, n)
    end function bifilar_rstar

    !> The cylinder with unequal cables (Figs. 4-6) as a platform of two cables, from the
    !! paper's raised start at 45 degrees: the mass centre follows the paper's model.
    subroutine test_bifilar(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(platform_t) :: pl
        type(bifilar_t) :: bsys
        type(platform_sys_t) :: sys
        type(platform_motion_t) :: mo
        type(status_t) :: st, st2
        real(dp) :: th(5), yb0(NSTATE), yb(NSTATE), y0(8), y(8), err, tau
        integer :: j
        p = cylinder_pendulum(1.8_dp)
        call raised_angles(p, 45.0_dp*deg, th, st)
        call solve_theta5(p, th, st)
        yb0 = chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp])
        pl = bifilar_platform(p)
        call check_platform(pl, st)
        call t%check('platform n = 2: the paper''s cylinder is accepted', st%code == 0)
        y0 = platform_state_of(p, pl, yb0)
        call platform_evaluate(pl, y0, mo, st)
        call t%check_close('platform n = 2: the start''s mass centre is the paper''s', &
                           maxval(abs(mo%rc - bifilar_rstar(p, yb0))), 0.0_dp, 0.0_dp, &
                           1.0e-14_dp)
        bsys%p = p
        sys%pl = pl
        err = 0.0_dp
        do j = 1, 5
            tau = 2.0_dp*j
            call integrate(bsys, yb0, tau, 1.0e-12_dp, 1.0e-14_dp, SOLVER_LSODA, yb, st)
            call integrate(sys, y0, tau, 1.0e-12_dp, 1.0e-14_dp, SOLVER_LSODA, y, st2)
            if (st%code /= 0 .or. st2%code /= 0) err = huge(1.0_dp)
            call platform_evaluate(pl, y, mo, st)
            err = max(err, maxval(abs(mo%rc - bifilar_rstar(p, yb))))
        end do
        call t%check_close('platform n = 2: the mass centre of the paper''s model over '// &
                           'tau = 0 ... 10', err, 0.0_dp, 0.0_dp, 2.0e-9_dp)
        write (*, '(a,es10.3)') '  platform n = 2 against the paper''s model, max |dR*|/b'': ', &
            err
    end subroutine test_bifilar

    ! ---------------------------------------------------------------------------------------
    !> A centred trifilar (R = 0.5, R' = 0.4, l = 1.2): the period of pure torsion is the
    !! paper's eqs. (45)-(48) with b = 2R, b' = 2R' (floquet's torsion_period) to 1e-10 at
    !! 10, 45 and 80 degrees; the motion stays pure torsion; the tensions add to the bifilar's
    !! T_BC + T_AD at the start and to m g l/h at rest.
    subroutine test_torsion(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_sys_t) :: sys
        type(platform_motion_t) :: mo
        type(pendulum_t) :: p
        type(motion_t) :: bm
        type(status_t) :: st
        real(dp), parameter :: r = 0.5_dp, rp = 0.4_dp, l = 1.2_dp
        real(dp) :: y0(6), per, perb, amp, ts, yb0(NSTATE), y(6), hh, worst, drift
        real(dp), parameter :: amps(3) = [10.0_dp, 45.0_dp, 80.0_dp]
        integer :: ia
        logical :: ok
        pl = regular(3, r, rp, l, [0.0_dp, 0.0_dp], 0.1_dp)
        call check_platform(pl, st)
        call t%check('platform torsion: the rig is accepted', st%code == 0)
        ! at rest the tensions add to m g l/h
        hh = sqrt(l**2 - (r - rp)**2)
        call platform_evaluate(pl, [pl%q_ref(pl%free(1:3)), 0.0_dp, 0.0_dp, 0.0_dp], mo, st)
        call t%check_close('platform torsion: the tensions at rest add to m g l/h', &
                           sum(mo%tension), MASS*GRAV*l/hh, 1.0e-13_dp, 0.0_dp)
        ! the bifilar equivalent: b = 2R, b' = 2R' (scaled by b'), I_v/(m b'^2)
        p = pendulum_t()
        p%big_b = r/rp
        p%big_l = l/(2.0_dp*rp)
        p%big_lp = p%big_l
        p%inertia = 0.09_dp/(MASS*(2.0_dp*rp)**2)
        p%r = 0.5_dp
        p%lambda = 0.0_dp
        ts = sqrt(2.0_dp*rp/GRAV)               ! the bifilar's unit of time
        worst = 0.0_dp
        drift = 0.0_dp
        sys%pl = pl
        do ia = 1, 3
            amp = amps(ia)*deg
            call platform_start(pl, amp, y0, st)
            call measure_period(sys, y0, 6, 1, 1.0e-13_dp, 1.0e-15_dp, SOLVER_LSODA, 100.0_dp, &
                                per, ok)
            call torsion_period(p, amp, 3, perb, st)
            worst = max(worst, abs(per/(perb*ts) - 1.0_dp))
            if (.not. ok) worst = huge(1.0_dp)
            ! pure torsion: no sway, no tilt after a period
            call integrate(sys, y0, per, 1.0e-13_dp, 1.0e-15_dp, SOLVER_LSODA, y, st)
            call platform_evaluate(pl, y, mo, st)
            drift = max(drift, maxval(abs(mo%q([1, 2, 5, 6]))), maxval(abs(mo%qd([1, 2, 5, 6]))))
            ! the tensions at the start: their sum is the bifilar's T_BC + T_AD
            if (ia == 2) then
                call torsion_start(p, amp, yb0, st)
                call evaluate(p, yb0, 0.0_dp, bm, st)
                call platform_evaluate(pl, y0, mo, st)
                call t%check_close('platform torsion: the tensions add to the paper''s '// &
                                   'T_BC + T_AD (b = 2R, b'' = 2R'')', sum(mo%tension), &
                                   (bm%t_bc + bm%t_ad)*MASS*GRAV, 1.0e-10_dp, 0.0_dp)
            end if
        end do
        call t%check_close('platform torsion: period = the paper''s eqs. (45)-(48) with '// &
                           'b = 2R, b'' = 2R''', worst, 0.0_dp, 0.0_dp, 1.0e-10_dp)
        call t%check_close('platform torsion: it stays pure torsion', drift, 0.0_dp, 0.0_dp, &
                           1.0e-11_dp)
        write (*, '(a,es10.3)') '  platform torsion period against eqs. (45)-(48), worst '// &
            'relative difference: ', worst
    end subroutine test_torsion

    ! ---------------------------------------------------------------------------------------
    !> The linearised model of doc/theory.md for a centred regular platform (R, R', l; mass
    !! centre cg_depth d below the attachments' plane; I_xx, I_yy, I_zz): torsion
    !! w^2 = m g R R'/(h I_zz); with inextensible cables the sways
    !! w^2 = m g (1/h + k^2 (R R'/(2h) + d)) / (m (1 - d k)^2 + I k^2), k = (R - R')/(h R'),
    !! I = I_yy (x) or I_xx (y); with elastic cables (n >= 3) the bounce
    !! w^2 = n (k_c c^2 + T a^2/l)/m and the pairs sway/tilt of the 2 x 2 problem below.
    subroutine test_frequencies(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_sys_t) :: sys
        type(platform_modes_t) :: md
        type(platform_elastic_t) :: el
        type(status_t) :: st
        real(dp), parameter :: r = 0.5_dp, rp = 0.4_dp, l = 1.2_dp, d = 0.1_dp
        real(dp) :: hh, kap, w_t, w_x, w_y, y0(6), per, err_lin, err_sim, qr(6), w2(6), ye(12)
        real(dp) :: ex(6), tension, kc, ll, a, c, cc
        logical :: ok
        integer :: it
        hh = sqrt(l**2 - (r - rp)**2)
        kap = (r - rp)/(hh*rp)
        w_t = MASS*GRAV*r*rp/(hh*0.09_dp)
        w_x = MASS*GRAV*(1.0_dp/hh + kap**2*(r*rp/(2.0_dp*hh) + d))/ &
              (MASS*(1.0_dp - d*kap)**2 + 0.06_dp*kap**2)
        w_y = MASS*GRAV*(1.0_dp/hh + kap**2*(r*rp/(2.0_dp*hh) + d))/ &
              (MASS*(1.0_dp - d*kap)**2 + 0.05_dp*kap**2)
        pl = regular(3, r, rp, l, [0.0_dp, 0.0_dp], d)
        call check_platform(pl, st)
        call linearise(pl, md, st)
        err_lin = maxval(abs(md%omega2(1:3)/[w_x, w_y, w_t] - 1.0_dp))
        call t%check_close('platform frequencies: linearise against the closed forms (n = 3)', &
                           err_lin, 0.0_dp, 0.0_dp, 1.0e-7_dp)
        ! the motion at small amplitude: torsion, sway along x, sway along y
        sys%pl = pl
        err_sim = 0.0_dp
        call platform_start(pl, 1.0e-4_dp, y0, st)
        call measure_period(sys, y0, 6, 2, 1.0e-12_dp, 1.0e-16_dp, SOLVER_LSODA, 100.0_dp, per, ok)
        err_sim = max(err_sim, abs((2.0_dp*pi/per)**2/w_t - 1.0_dp))
        call platform_start(pl, 0.0_dp, y0, st, sway=[1.0e-5_dp, 0.0_dp])
        call measure_period(sys, y0, 4, 2, 1.0e-12_dp, 1.0e-16_dp, SOLVER_LSODA, 100.0_dp, per, ok)
        err_sim = max(err_sim, abs((2.0_dp*pi/per)**2/w_x - 1.0_dp))
        call platform_start(pl, 0.0_dp, y0, st, sway=[0.0_dp, 1.0e-5_dp])
        call measure_period(sys, y0, 5, 2, 1.0e-12_dp, 1.0e-16_dp, SOLVER_LSODA, 100.0_dp, per, ok)
        err_sim = max(err_sim, abs((2.0_dp*pi/per)**2/w_y - 1.0_dp))
        call t%check_close('platform frequencies: the motion at small amplitude (torsion, '// &
                           'two sways)', err_sim, 0.0_dp, 0.0_dp, 1.0e-7_dp)
        write (*, '(a,2es10.3)') '  platform n = 3 frequencies: linearise, motion against '// &
            'the closed forms: ', err_lin, err_sim
        ! elastic n = 4: the rest's loaded length l, tension T: n T h/l = m g, l = L0 + T/k_c
        el%pl = regular(4, r, rp, l, [0.0_dp, 0.0_dp], d)
        el%stiffness = 1.0e4_dp
        call platform_prepare(el%pl, st)
        call pe_rest_pose(el, qr, st)
        call pe_linearise(el, qr, w2, st)
        kc = el%stiffness*MASS*GRAV/l
        ll = l
        do it = 1, 100
            hh = sqrt(ll**2 - (r - rp)**2)
            tension = MASS*GRAV*ll/(4.0_dp*hh)
            ll = l + tension/kc
        end do
        hh = sqrt(ll**2 - (r - rp)**2)
        a = (rp - r)/ll
        c = hh/ll
        ex(1:2) = sway_tilt(0.06_dp)
        ex(3:4) = sway_tilt(0.05_dp)
        ex(5) = MASS*GRAV*r*rp/(hh*0.09_dp)
        ex(6) = 4.0_dp*(kc*c**2 + tension*a**2/ll)/MASS
        cc = maxval(abs(sorted(w2)/sorted(ex) - 1.0_dp))
        call t%check_close('platform frequencies: elastic n = 4 linearised against the '// &
                           'closed forms (bounce, tilts, sways, torsion)', cc, 0.0_dp, 0.0_dp, &
                           1.0e-7_dp)
        ! the bounce at small amplitude: the masters' stretches raised alike
        ye = 0.0_dp
        ye(1:6) = qr
        ye(4:6) = qr(4:6) + 1.0e-9_dp
        call measure_period(el, ye, 10, 3, 1.0e-11_dp, 1.0e-18_dp, SOLVER_RADAU, 10.0_dp, per, ok)
        call t%check_close('platform frequencies: the elastic bounce at small amplitude', &
                           (2.0_dp*pi/per)**2, ex(6), 1.0e-6_dp, 0.0_dp)
        write (*, '(a,2es10.3)') '  platform n = 4 elastic frequencies: linearise, bounce: ', &
            cc, abs((2.0_dp*pi/per)**2/ex(6) - 1.0_dp)
    contains
        !> The two roots of det(K - w^2 M) of the sway along x with the tilt about y
        !! (inertia iy; or y with x).
        function sway_tilt(iy) result(w)
            real(dp), intent(in) :: iy
            real(dp) :: w(2), k11, k12, k22, m11, m12, m22, f, tr, dt
            k11 = kc*2.0_dp*a**2 + (tension/ll)*(4.0_dp - 2.0_dp*a**2)
            k12 = (kc - tension/ll)*2.0_dp*a*c*rp
            k22 = 2.0_dp*(kc*c**2*rp**2 + (tension/ll)*a**2*rp**2 - tension*a*rp) + MASS*GRAV*d
            m11 = MASS
            m12 = -MASS*d
            m22 = MASS*d**2 + iy
            f = m11*m22 - m12**2
            tr = k11*m22 + k22*m11 - 2.0_dp*k12*m12
            dt = k11*k22 - k12**2
            w = [(tr - sqrt(tr**2 - 4.0_dp*f*dt))/(2.0_dp*f), (tr + sqrt(tr**2 - 4.0_dp*f*dt))/ &
                 (2.0_dp*f)]
        end function sway_tilt
        function sorted(v) result(s)
            real(dp), intent(in) :: v(:)
            real(dp) :: s(size(v)), x
            integer :: i, j
            s = v
            do i = 2, size(s)
                x = s(i)
                j = i - 1
                do while (j >= 1)
                    if (s(j) <= x) exit
                    s(j + 1) = s(j)
                    j = j - 1
                end do
                s(j + 1) = x
            end do
        end function sorted
    end subroutine test_frequencies

    ! ---------------------------------------------------------------------------------------
    !> Energy over 100 torsion periods: the off-centre trifilar at 45 degrees (LSODA,
    !! through the run loop), the undamped elastic quadrifilar (Radau).
    subroutine test_energy(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_run_t) :: run
        type(keep_t) :: sink
        type(platform_elastic_t) :: el
        type(status_t) :: st
        real(dp), parameter :: rtol = 1.0e-10_dp
        real(dp) :: y0(6), e0, de, times(0:100), per, qr(6), ye(12), yend(12)
        integer :: k, steps
        pl = regular(3, 0.5_dp, 0.4_dp, 1.2_dp, [0.05_dp, 0.02_dp], 0.1_dp)
        call check_platform(pl, st)
        call platform_start(pl, 45.0_dp*deg, y0, st)
        per = 2.0_dp*pi*sqrt(0.09_dp*1.2_dp/(MASS*GRAV*0.5_dp*0.4_dp))
        times = [(per*k, k = 0, 100)]
        call platform_run_start(run, pl, y0, rtol, rtol*1.0e-2_dp, SOLVER_LSODA, times(100), st)
        call drive(run, times, sink, st)
        call t%check('platform energy: 100 periods run', st%code == 0)
        e0 = platform_energy(pl, y0)
        de = 0.0_dp
        do k = 1, 100
            de = max(de, abs(platform_energy(pl, sink%y(:, k)) - e0))
        end do
        de = de/(MASS*GRAV*1.2_dp)
        call t%check_close('platform energy: conserved over 100 periods (n = 3, LSODA, '// &
                           'rtol 1e-10; over m g l)', de, 0.0_dp, 0.0_dp, 10.0_dp*rtol)
        write (*, '(a,es10.3,a,i0,a)') '  platform n = 3 energy drift over 100 periods: ', de, &
            ' m g l (', run%nsteps, ' steps)'
        ! elastic n = 4, undamped, from a start on the slow motion (pe_start)
        el%pl = regular(4, 0.5_dp, 0.4_dp, 1.2_dp, [0.05_dp, 0.02_dp], 0.1_dp)
        el%stiffness = 1.0e4_dp
        call platform_prepare(el%pl, st)
        call pe_rest_pose(el, qr, st)
        call pe_start(el, qr, 10.0_dp*deg, ye, st)
        e0 = pe_energy(el, ye)
        call integrate(el, ye, 100.0_dp*per, rtol, rtol*1.0e-2_dp, SOLVER_RADAU, yend, st, steps)
        call t%check('platform energy: the elastic run ends', st%code == 0)
        de = abs(pe_energy(el, yend) - e0)/(MASS*GRAV*1.2_dp)
        call t%check_close('platform energy: conserved over 100 periods (elastic n = 4, '// &
                           'k = 1e4, Radau, rtol 1e-10)', de, 0.0_dp, 0.0_dp, 10.0_dp*rtol)
        write (*, '(a,es10.3,a,i0,a)') '  platform elastic n = 4 energy drift: ', de, &
            ' m g l (', steps, ' steps)'
    end subroutine test_energy

    ! ---------------------------------------------------------------------------------------
    !> Elastic n = 3 from the inextensible start (loaded lengths), k = 1e3 ... 1e7: the
    !! difference from the inextensible model over 3 s falls as 1/k.
    subroutine test_elastic_limit(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_sys_t) :: sys
        type(platform_elastic_t) :: el
        type(status_t) :: st
        real(dp) :: y0(6), y(6), ye0(12), ye(12), err(5), kk(5), slope
        integer :: i
        logical :: ok
        pl = regular(3, 0.5_dp, 0.4_dp, 1.2_dp, [0.05_dp, 0.02_dp], 0.1_dp)
        call check_platform(pl, st)
        call platform_start(pl, 30.0_dp*deg, y0, st, sway=[0.02_dp, 0.0_dp])
        sys%pl = pl
        call integrate(sys, y0, 3.0_dp, 1.0e-12_dp, 1.0e-14_dp, SOLVER_LSODA, y, st)
        ok = st%code == 0
        do i = 1, 5
            kk(i) = 10.0_dp**(i + 2)
            el = platform_elastic_t()
            el%pl = pl
            el%stiffness = kk(i)
            call pe_from_inextensible(el, y0, ye0, st)
            call integrate(el, ye0, 3.0_dp, 1.0e-11_dp, 1.0e-13_dp, SOLVER_RADAU, ye, st)
            ok = ok .and. st%code == 0
            err(i) = maxval(abs(ye(1:3) - y(1:3)))
        end do
        slope = log(err(5)/err(1))/log(kk(5)/kk(1))
        call t%check('platform elastic n = 3: the runs end', ok)
        call t%check_close('platform elastic n = 3: error falls as 1/k (log-log slope)', slope, &
                           -1.0_dp, 0.0_dp, 0.01_dp)
        call t%check('platform elastic n = 3: error below 1e-6 at k = 1e6', err(4) < 1.0e-6_dp)
        write (*, '(a,5es10.3)') '  platform elastic n = 3 against inextensible, k = 1e3 ... '// &
            '1e7: ', err
    end subroutine test_elastic_limit

    !> Elastic n = 2 (the cylinder with l' = 1.8) from the paper's raised start: the mass
    !! centre's difference from the paper's model over tau = 0 ... 6 falls as 1/k.
    subroutine test_elastic_bifilar(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(platform_t) :: pl
        type(bifilar_t) :: bsys
        type(platform_elastic_t) :: el
        type(pe_motion_t) :: mo
        type(status_t) :: st
        real(dp) :: th(5), yb0(NSTATE), yb(NSTATE), y0(8), ye0(12), ye(12), err(3), slope
        integer :: i
        logical :: ok
        p = cylinder_pendulum(1.8_dp)
        call raised_angles(p, 45.0_dp*deg, th, st)
        call solve_theta5(p, th, st)
        yb0 = chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp])
        pl = bifilar_platform(p)
        call check_platform(pl, st)
        y0 = platform_state_of(p, pl, yb0)
        bsys%p = p
        call integrate(bsys, yb0, 6.0_dp, 1.0e-12_dp, 1.0e-14_dp, SOLVER_LSODA, yb, st)
        ok = st%code == 0
        do i = 1, 3
            el = platform_elastic_t()
            el%pl = pl
            el%stiffness = 10.0_dp**(i + 3)
            call pe_from_inextensible(el, y0, ye0, st)
            call integrate(el, ye0, 6.0_dp, 1.0e-11_dp, 1.0e-13_dp, SOLVER_RADAU, ye, st)
            ok = ok .and. st%code == 0
            call pe_evaluate(el, ye, mo, st)
            err(i) = maxval(abs(mo%rc - bifilar_rstar(p, yb)))
        end do
        slope = log(err(3)/err(1))/log(100.0_dp)
        call t%check('platform elastic n = 2: the runs end', ok)
        call t%check_close('platform elastic n = 2: error from the paper''s model falls as '// &
                           '1/k (log-log slope)', slope, -1.0_dp, 0.0_dp, 0.02_dp)
        write (*, '(a,3es10.3)') '  platform elastic n = 2 against the paper''s model, '// &
            'k = 1e4, 1e5, 1e6: ', err
    end subroutine test_elastic_bifilar

    ! ---------------------------------------------------------------------------------------
    !> A test-mass series on a trifilar with parallel cables (R = R' = 0.135 m, l = 1 m): a
    !! 0.848 kg platform (a disc of radius 0.15 m) carries a 20.94 g mass at r = 0 ... 0.75 m,
    !! which moves the mass centre up to e = 18 mm off the axis.  At small amplitude the
    !! torsion turns about the mass centre with the restoring torque per radian
    !! kappa = M g (R^2 - e^2)/L.  The periods of the platform model and of the independent
    !! model agree; kappa = 4 pi^2 I_cg/T^2 equals M g (R^2 - e^2)/L to 1e-6 and is off by
    !! e^2/R^2 (1.8 % at 0.75 m) when the offset is ignored; the series' slope dI/d(r^2) is
    !! the test mass with the offset, off by what the formula predicts without it.
    subroutine test_mass_series(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: nk = 6
        real(dp), parameter :: rr = 0.135_dp, ll = 1.0_dp, m0 = 0.848_dp, mt = 0.02094_dp, &
                               gg = 9.81_dp, amp = 1.0e-4_dp
        type(platform_t) :: pl
        type(platform_sys_t) :: sys
        type(ref_body_t) :: rb
        type(status_t) :: st
        real(dp) :: j0(3, 3), jc(3, 3), c0(3), pt(3), cm(3), mm, e, per(nk), perr(nk), rk(nk), &
                    kap, kap_pred, worst, worst_ref, naive_dev, icg(nk), iax(nk), inai(nk), &
                    ipred(nk), y0(6), yr0(REF_NSTATE), slope, slope_naive, slope_pred
        integer :: k
        logical :: ok, okr
        j0 = 0.0_dp
        j0(1, 1) = 0.25_dp*m0*0.15_dp**2
        j0(2, 2) = j0(1, 1)
        j0(3, 3) = 0.5_dp*m0*0.15_dp**2
        c0 = [0.0_dp, 0.0_dp, -0.01_dp]
        mm = m0 + mt
        worst = 0.0_dp
        worst_ref = 0.0_dp
        do k = 1, nk
            rk(k) = 0.15_dp*(k - 1)
            pt = [rk(k), 0.0_dp, 0.0_dp]
            cm = (m0*c0 + mt*pt)/mm
            jc = j0 + m0*shift(c0 - cm) + mt*shift(pt - cm)
            pl = regular_platform(3, rr, rr, ll, mm, jc, cm(1:2), -cm(3), gg)
            call check_platform(pl, st)
            ok = st%code == 0
            sys%pl = pl
            call platform_start(pl, amp, y0, st)
            call measure_period(sys, y0, 6, 3, 1.0e-12_dp, 1.0e-17_dp, SOLVER_LSODA, 100.0_dp, &
                                per(k), ok)
            ! the independent model from its own start: turned about the mass centre's vertical
            rb = reference_of(pl)
            call reference_start(rb, amp, yr0, okr)
            call measure_period(rb, yr0, 13, 3, 1.0e-12_dp, 1.0e-17_dp, SOLVER_LSODA, 100.0_dp, &
                                perr(k), okr)
            if (.not. (ok .and. okr)) worst = huge(1.0_dp)
            worst_ref = max(worst_ref, abs(per(k)/perr(k) - 1.0_dp))
            e = norm2(cm(1:2))
            icg(k) = jc(3, 3)
            kap = 4.0_dp*pi**2*icg(k)/per(k)**2
            kap_pred = mm*gg*(rr**2 - e**2)/ll
            worst = max(worst, abs(kap/kap_pred - 1.0_dp))
            if (k == nk) naive_dev = mm*gg*rr**2/ll/kap - 1.0_dp
            ! the moment about the axis measured with the offset, and without it
            iax(k) = kap_pred*per(k)**2/(4.0_dp*pi**2) + mm*e**2
            inai(k) = mm*gg*rr**2/ll*per(k)**2/(4.0_dp*pi**2)
            ipred(k) = icg(k)*rr**2/(rr**2 - e**2)
        end do
        call t%check_close('platform test mass: the periods of the independent model', &
                           worst_ref, 0.0_dp, 0.0_dp, 1.0e-9_dp)
        call t%check_close('platform test mass: kappa = M g (R^2 - e^2)/L', worst, 0.0_dp, &
                           0.0_dp, 1.0e-6_dp)
        e = mt*rk(nk)/mm
        call t%check_close('platform test mass: ignoring the offset is off by e^2/(R^2 - e^2)', &
                           naive_dev, e**2/(rr**2 - e**2), 1.0e-6_dp, 0.0_dp)
        call t%check('platform test mass: that is 1.8 % at 0.75 m', &
                     naive_dev > 0.017_dp .and. naive_dev < 0.019_dp)
        slope = fit_slope(rk**2, iax)
        slope_naive = fit_slope(rk**2, inai)
        slope_pred = fit_slope(rk**2, ipred)
        call t%check_close('platform test mass: the slope dI/d(r^2) with the offset is the '// &
                           'test mass', slope, mt, 1.0e-6_dp, 0.0_dp)
        call t%check_close('platform test mass: without the offset it is off as predicted', &
                           slope_naive/mt - 1.0_dp, slope_pred/mt - 1.0_dp, 0.0_dp, 1.0e-6_dp)
        write (*, '(a,es10.3,a,es10.3,a,f7.4,a,f7.4,a)') '  platform test mass: periods '// &
            'against the independent model ', worst_ref, ', kappa ', worst, &
            '; ignoring the offset: kappa +', 100*naive_dev, ' %, slope ', &
            100*(slope_naive/mt - 1.0_dp), ' %'
    contains
        !> The parallel-axis term of a unit mass at offset u: |u|^2 I - u u^T.
        pure function shift(u) result(s)
            real(dp), intent(in) :: u(3)
            real(dp) :: s(3, 3)
            integer :: i
            s = -spread(u, 2, 3)*spread(u, 1, 3)
            do i = 1, 3
                s(i, i) = s(i, i) + dot_product(u, u)
            end do
        end function shift
    end subroutine test_mass_series

    ! ---------------------------------------------------------------------------------------
    !> The test-mass series of the published trifilar fitted as identify fits it: a 20.94 g
    !! mass at r = 0 ... 0.75 m on a 0.848 kg platform (R = R' = 0.8 m, l = 1 m, the
    !! platform's moment 0.14 kg m^2 about its axis, the test mass at the height of the
    !! platform's mass centre, 10 mm below the attachments), the mass centre up to 18 mm off
    !! the axis.  The periods come from the independent model (maximal coordinates, the
    !! cables as holonomic constraints) at 1e-4 rad; each is inverted by period_inversion on
    !! the platform's rig (rig_t of 3 cables, its mass centre off the axis: the platform's
    !! periodic torsion, no parallel-axis correction).  The moment about the axis, I1 + M e^2,
    !! grows with r^2 by the test mass to 1e-6; the inversion with the offset ignored (the
    !! centred body's pure torsion) gives the slope that M g (R^2 - e^2)/L predicts (the
    !! moment about the mass centre taken for the moment about the axis, R^2/(R^2 - e^2)
    !! times it), about 1.8 % low as in the published data.
    subroutine test_mass_identify(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: nk = 6
        real(dp), parameter :: rr = 0.8_dp, ll = 1.0_dp, m0 = 0.848_dp, mt = 0.02094_dp, &
                               gg = 9.81_dp, amp = 1.0e-4_dp, depth = 0.01_dp, &
                               jz0 = 0.14_dp, jx0 = 0.075_dp
        type(platform_t) :: pl
        type(ref_body_t) :: rb
        type(status_t) :: st
        type(rig_t) :: rg, rn
        type(accuracy_t) :: acc
        type(input_u_t) :: u
        type(period_fit_t) :: fit, fitn
        real(dp) :: jc(3, 3), cm(3), mm, e, perr(nk), rk(nk), iax(nk), inai(nk), ipred(nk), &
                    yr0(REF_NSTATE), slope, slope_naive, slope_pred, worst_i1
        integer :: k
        logical :: ok, okr
        mm = m0 + mt
        ok = .true.
        worst_i1 = 0.0_dp
        acc%rtol = 1.0e-12_dp
        acc%atol = 1.0e-16_dp
        acc%method = SOLVER_LSODA
        do k = 1, nk
            rk(k) = 0.15_dp*(k - 1)
            e = mt*rk(k)/mm
            cm = [e, 0.0_dp, -depth]
            ! the platform (its mass centre on the axis) and the test mass, about the whole's
            ! mass centre: every offset along x, so the tensor stays diagonal
            jc = 0.0_dp
            jc(1, 1) = jx0
            jc(2, 2) = jx0 + m0*e**2 + mt*(rk(k) - e)**2
            jc(3, 3) = jz0 + m0*e**2 + mt*(rk(k) - e)**2
            pl = regular_platform(3, rr, rr, ll, mm, jc, cm(1:2), depth, gg)
            call check_platform(pl, st)
            ok = ok .and. st%code == 0
            rb = reference_of(pl)
            call reference_start(rb, amp, yr0, okr)
            call measure_period(rb, yr0, 13, 3, 1.0e-12_dp, 1.0e-17_dp, SOLVER_LSODA, 100.0_dp, &
                                perr(k), okr)
            ok = ok .and. okr
            ! the rig identify builds from the deck: cables = 3, b = 2 R, the mass centre
            ! (r, lambda) at the offset e along x, cg_depth below; inertia(1) the start guess
            rg = rig_t()
            rg%cables = 3
            rg%b = 2.0_dp*rr
            rg%b_prime = 2.0_dp*rr
            rg%l = ll
            rg%l_prime = ll
            rg%g = gg
            rg%mass = mm
            rg%inertia = [0.9_dp*jc(3, 3), jc(1, 1), jc(2, 2)]
            rg%c_v = 0.0_dp
            rg%c_q = 0.0_dp
            rg%r = sqrt((rr + e)**2 + depth**2)
            rg%lambda = atan2(depth, rr + e)
            call invert_periods(rg, acc, [perr(k)], [amp/deg], u, fit, st)
            ok = ok .and. st%code == 0
            worst_i1 = max(worst_i1, abs(fit%i1/jc(3, 3) - 1.0_dp))
            iax(k) = fit%i1 + mm*e**2
            ! the offset ignored: the centred body
            rn = rg
            rn%r = sqrt(rr**2 + depth**2)
            rn%lambda = atan2(depth, rr)
            call invert_periods(rn, acc, [perr(k)], [amp/deg], u, fitn, st)
            ok = ok .and. st%code == 0
            inai(k) = fitn%i1
            ipred(k) = jc(3, 3)*rr**2/(rr**2 - e**2)
        end do
        call t%check('platform identify test mass: the independent model''s periods are '// &
                     'inverted', ok)
        slope = fit_slope(rk**2, iax)
        slope_naive = fit_slope(rk**2, inai)
        slope_pred = fit_slope(rk**2, ipred)
        call t%check_close('platform identify test mass: I1 about the mass centre', &
                           worst_i1, 0.0_dp, 0.0_dp, 1.0e-7_dp)
        call t%check_close('platform identify test mass: the slope dI/d(r^2) is the test '// &
                           'mass', slope, mt, 1.0e-6_dp, 0.0_dp)
        call t%check_close('platform identify test mass: without the offset the slope is '// &
                           'M g (R^2 - e^2)/L''s', slope_naive/mt - 1.0_dp, &
                           slope_pred/mt - 1.0_dp, 0.0_dp, 1.0e-5_dp)
        call t%check('platform identify test mass: that is about 1.8 % low', &
                     slope_naive/mt - 1.0_dp < -0.016_dp .and. slope_naive/mt - 1.0_dp > -0.020_dp)
        write (*, '(a,es10.3,a,es10.3,a,f8.4,a,f8.4,a)') '  platform identify test mass: '// &
            'worst I1 ', worst_i1, ', slope - m ', slope/mt - 1.0_dp, &
            '; offset ignored: slope ', 100*(slope_naive/mt - 1.0_dp), ' % (predicted ', &
            100*(slope_pred/mt - 1.0_dp), ' %)'
    end subroutine test_mass_identify

    !> Least-squares slope of y against x.
    pure real(dp) function fit_slope(x, y) result(s)
        real(dp), intent(in) :: x(:), y(:)
        real(dp) :: mx, my
        mx = sum(x)/size(x)
        my = sum(y)/size(y)
        s = sum((x - mx)*(y - my))/sum((x - mx)**2)
    end function fit_slope

    !> The reference model's start: from its rest (the body level, the cables vertical: R = R')
    !! turned by amp about the vertical through the mass centre, then its height and tilt
    !! found by Newton's method on the constraints (differences for the Jacobian), at rest.
    subroutine reference_start(rb, amp, y, ok)
        type(ref_body_t), intent(in) :: rb
        real(dp), intent(in) :: amp
        real(dp), intent(out) :: y(REF_NSTATE)
        logical, intent(out) :: ok
        real(dp) :: u(3), g(rb%n), gd(rb%n), jac(3, 3), gp(rb%n), du(3), h, yy(REF_NSTATE), &
                    c(2)
        integer :: it, j
        type(status_t) :: st
        ! rest: body points under the supports, cables vertical: the mass centre under
        ! S_1 - b_1, at height S_1z - l_1 - b_1z
        c = rb%s(1:2, 1) - rb%b(1:2, 1)
        u = [rb%s(3, 1) - rb%l(1) - rb%b(3, 1), 0.0_dp, 0.0_dp]   ! z, tilt x, tilt y
        do it = 1, 30
            yy = state(u)
            call ref_constraints(rb, yy, g, gd)
            if (maxval(abs(g)) < 1.0e-16_dp) exit
            h = 1.0e-7_dp
            do j = 1, 3
                du = 0.0_dp
                du(j) = h
                call ref_constraints(rb, state(u + du), gp, gd)
                jac(:, j) = (gp(1:3) - g(1:3))/h
            end do
            du = -g(1:3)
            call la_solve_3(jac, du, st)
            u = u + du
        end do
        yy = state(u)
        call ref_constraints(rb, yy, g, gd)
        ok = maxval(abs(g)) < 1.0e-14_dp
        y = yy
    contains
        function state(uu) result(ys)
            real(dp), intent(in) :: uu(3)
            real(dp) :: ys(REF_NSTATE)
            ys = 0.0_dp
            ys(1:2) = c
            ys(3) = uu(1)
            ys(7:10) = ref_quat_of_yaw_tilt(amp, uu(2), uu(3))
        end function state
    end subroutine reference_start

    subroutine la_solve_3(a, b, st)
        real(dp), intent(inout) :: a(3, 3), b(3)
        type(status_t), intent(out) :: st
        call la_solve(a, b, st)
    end subroutine la_solve_3

    ! ---------------------------------------------------------------------------------------
    !> The rest pose of an off-centre trifilar is an equilibrium (tilted, at rest, tensions
    !! balancing the weight); the tipping height of a centred trifilar is the closed form
    !! d = -(R R'/(2h) + h R'^2/(R - R')^2); bad platforms give a status with one line.
    subroutine test_rest(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_motion_t) :: mo
        type(status_t) :: st
        real(dp), parameter :: r = 0.5_dp, rp = 0.3_dp, l = 0.6_dp
        real(dp) :: depth, hh, d_tip, y(6), sup(3, 3), bod(3, 3)
        logical :: found
        pl = regular(3, 0.5_dp, 0.4_dp, 1.2_dp, [0.06_dp, -0.03_dp], 0.1_dp)
        call check_platform(pl, st)
        y = 0.0_dp
        y(1:3) = pl%q_ref(pl%free(1:3))
        call platform_evaluate(pl, y, mo, st)
        call t%check('platform rest: accepted and tilted off the axis', st%code == 0 .and. &
                     max(abs(mo%q(5)), abs(mo%q(6))) > 1.0e-3_dp)
        call t%check_close('platform rest: an equilibrium (no acceleration)', &
                           maxval(abs(mo%udot(1:3))), 0.0_dp, 0.0_dp, 1.0e-12_dp)
        call t%check_close('platform rest: the mass centre hangs under the tensions'' '// &
                           'resultant (no acceleration of the mass centre)', &
                           maxval(abs(mo%ac)), 0.0_dp, 0.0_dp, 1.0e-12_dp)
        ! the tipping height of a centred trifilar (R = 0.5, R' = 0.3, l = 0.6)
        hh = sqrt(l**2 - (r - rp)**2)
        d_tip = -(r*rp/(2.0_dp*hh) + hh*rp**2/(r - rp)**2)
        pl = regular(3, r, rp, l, [0.0_dp, 0.0_dp], 0.05_dp)
        call check_platform(pl, st)
        call tipping_depth(pl, depth, found, st)
        call t%check_close('platform rest: tipping height = -(R R''/(2h) + h R''^2/(R - R'')^2)', &
                           depth, d_tip, 1.0e-8_dp, 0.0_dp)
        write (*, '(a,2es16.8)') '  platform tipping cg_depth, found and closed form: ', &
            depth, d_tip
        ! bad platforms
        pl = regular(3, r, rp, l, [0.0_dp, 0.0_dp], d_tip - 0.05_dp)
        call check_platform(pl, st)
        call t%check('platform bad: a body above its tipping height', &
                     st%code /= 0 .and. index(st%msg, 'tips over') > 0 .and. &
                     index(st%msg, sci(d_tip)) > 0 .and. one_line(st%msg))
        write (*, '(a)') '  '//st%msg
        sup(:, 1) = [0.0_dp, 0.0_dp, 0.0_dp]
        sup(:, 2) = [1.0_dp, 0.0_dp, 0.0_dp]
        sup(:, 3) = [0.0_dp, 1.0_dp, 0.0_dp]
        bod = sup*0.5_dp
        bod(:, 3) = [1.0_dp, 0.0_dp, 0.0_dp]
        pl = general_platform(3, sup, bod, [1.0_dp, 1.0_dp, 1.0_dp], 1.0_dp, body_inertia(), &
                              [0.2_dp, 0.0_dp], 0.1_dp, GRAV)
        call check_platform(pl, st)
        call t%check('platform bad: collinear body points', st%code /= 0 .and. &
                     index(st%msg, 'collinear') > 0 .and. one_line(st%msg))
        bod = sup*0.5_dp
        sup(:, 3) = [2.0_dp, 0.0_dp, 0.0_dp]
        pl = general_platform(3, sup, bod, [1.0_dp, 1.0_dp, 1.0_dp], 1.0_dp, body_inertia(), &
                              [0.2_dp, 0.1_dp], 0.1_dp, GRAV)
        call check_platform(pl, st)
        call t%check('platform bad: collinear support points', st%code /= 0 .and. &
                     index(st%msg, 'collinear') > 0 .and. one_line(st%msg))
        sup(:, 3) = [0.0_dp, 1.0_dp, 2.0_dp]     ! support 3 two metres higher, its cable 0.5 m
        pl = general_platform(3, sup, bod, [1.0_dp, 1.0_dp, 0.5_dp], 1.0_dp, body_inertia(), &
                              [0.15_dp, 0.15_dp], 0.1_dp, GRAV)
        call check_platform(pl, st)
        call t%check('platform bad: a length shorter than the height difference', &
                     st%code /= 0 .and. index(st%msg, 'height difference') > 0 .and. &
                     one_line(st%msg))
        write (*, '(a)') '  '//st%msg
        pl = regular(3, 0.5_dp, 0.4_dp, 0.05_dp, [0.0_dp, 0.0_dp], 0.1_dp)
        call check_platform(pl, st)
        call t%check('platform bad: cables shorter than the gap R - R''', st%code /= 0 .and. &
                     one_line(st%msg))
        pl = regular(4, 0.5_dp, 0.4_dp, 1.2_dp, [0.0_dp, 0.0_dp], 0.1_dp)
        call check_platform(pl, st)
        call t%check('platform bad: n = 4 inextensible is refused', st%code /= 0 .and. &
                     index(st%msg, 'indeterminate') > 0 .and. one_line(st%msg))
        pl = regular(3, 0.5_dp, 0.4_dp, 1.2_dp, [-0.3_dp, 0.0_dp], 0.1_dp)
        call check_platform(pl, st)
        call t%check('platform bad: the mass centre outside the attachments', &
                     st%code /= 0 .and. one_line(st%msg))
        write (*, '(a)') '  '//st%msg
    contains
        pure logical function one_line(s)
            character(len=*), intent(in) :: s
            one_line = len_trim(s) > 0 .and. index(s, new_line('a')) == 0
        end function one_line
    end subroutine test_rest

    ! ---------------------------------------------------------------------------------------
    !> A trifilar with parallel cables (R = R' = 0.5, l = 0.6), its mass centre 0.3 above
    !! the attachments, thrown sideways at 4 m/s: the inertia forces above the plane unload a
    !! cable while all still hang below the horizontal.  The inextensible run stops where
    !! it goes slack (ERR_MODEL, the time located in the step, the tension there ~0); the
    !! elastic model of the same rig runs on through slack and snap, its slack time and
    !! switches counted.
    subroutine test_slack(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_run_t) :: run, erun
        type(keep_t) :: sink
        type(platform_elastic_t) :: el
        type(platform_motion_t) :: mo
        type(status_t) :: st, st2
        real(dp) :: y0(6), ye0(12), times(0:40), ts, y(6)
        integer :: k
        pl = regular(3, 0.5_dp, 0.5_dp, 0.6_dp, [0.0_dp, 0.0_dp], -0.3_dp)
        call check_platform(pl, st)
        call platform_start(pl, 0.0_dp, y0, st)
        y0(4) = 4.0_dp                          ! thrown along x
        times = [(0.01_dp*k, k = 0, 40)]
        call platform_run_start(run, pl, y0, 1.0e-10_dp, 1.0e-12_dp, SOLVER_LSODA, times(40), st)
        call drive(run, times, sink, st)
        call t%check('platform slack: the inextensible run stops where a cable goes slack', &
                     st%code == ERR_MODEL .and. index(st%msg, 'slack') > 0)
        write (*, '(a)') '  '//st%msg
        ! the located time: the tensions there are 0 to the bisection's resolution
        ts = run%t_cur
        call run%solver%dense(0.5_dp*(run%t_prev + run%t_cur), 0, y, st2)
        k = index(st%msg, 't = ')
        if (k > 0) read (st%msg(k + 4:), *) ts
        call run%solver%dense(ts, 0, y, st2)
        call platform_evaluate(pl, y, mo, st2)
        call t%check_close('platform slack: the smallest tension at the located time', &
                           minval(mo%tension), 0.0_dp, 0.0_dp, 1.0e-3_dp*MASS*GRAV)
        ! the elastic model: a centred trifilar at rest whose cables are shortened at 1 m/s
        ! throws the body up; it flies free for about 2 v/g and snaps the cables taut again
        pl = regular(3, 0.5_dp, 0.5_dp, 0.6_dp, [0.0_dp, 0.0_dp], 0.1_dp)
        call check_platform(pl, st)
        call platform_start(pl, 0.0_dp, y0, st)
        el%pl = pl
        el%stiffness = 1.0e4_dp
        el%damping = 0.1_dp
        call pe_from_inextensible(el, y0, ye0, st)
        ye0(10:12) = -1.0_dp
        times = [(0.01_dp*k, k = 0, 40)]
        call elastic_run_start(erun, el, ye0, 1.0e-9_dp, 1.0e-11_dp, SOLVER_RADAU, times(40), st)
        deallocate (sink%y)
        call drive(erun, times, sink, st)
        call t%check('platform slack: the elastic run goes through slack and snap', &
                     st%code == 0 .and. erun%n_switches >= 2)
        call t%check_close('platform slack: each cable''s first slack interval is the '// &
                           'free flight, 2 v/g', maxval(abs(erun%first_slack(1:3) - &
                                                            2.0_dp/GRAV)), 0.0_dp, 0.0_dp, &
                           0.01_dp*2.0_dp/GRAV)
        write (*, '(a,i0,a,3es10.3,a,3es10.3,a,es10.3)') '  platform elastic slack: ', &
            erun%n_switches, ' switches, slack time ', erun%slack_time(1:3), &
            ', first interval ', erun%first_slack(1:3), ', 2 v/g = ', 2.0_dp/GRAV
        if (st%code /= 0) write (*, '(a)') '  '//st%msg
    end subroutine test_slack

end module test_platform
