!> Tests of the elastic-cable model (module elastic_model): conversions from and to the
!! paper's coordinates, Newton-Euler against the paper's equations, energy, convergence to
!! the inextensible model as the stiffness grows, stiffness (BDF), slack cables.
module test_elastic
    use kinds, only: dp, pi, deg
    use status, only: status_t
    use testing, only: tester_t
    use text, only: itoa
    use test_model, only: cylinder
    use geometry, only: pendulum_t, beta_coeffs
    use start_pose, only: raised_angles, solve_theta5
    use bifilar_model, only: bifilar_t, motion_t, chart_state, evaluate, chart_energy
    use elastic_model, only: elastic_t, elastic_cables_t, elastic_from_angles, elastic_start, &
                             elastic_evaluate, elastic_chart, elastic_energy, ELASTIC_NSTATE, &
                             natural_lengths, elastic_atol, CABLE_BC, CABLE_AD, CABLE_AUTO, &
                             CABLE_TAUT, CABLE_SLACK, cable_switch
    use elastic_solver, only: elastic_solver_t, slack_interval_t, SOLVER_LSODA
    use lsoda, only: lsoda_t, METHOD_BDF
    use lapack_wrap, only: la_eig
    use ode_system, only: integrator_stats_t
    use unused_arg, only: unused
    implicit none
    private

    public :: run_elastic_tests

    !> Torsional period of the cylinder on l = 2 b', b = b' (small amplitude, tau units):
    !! 4 pi sqrt(I1 l/(m g b^2)) = 2 pi.
    real(dp), parameter :: TORSION_PERIOD = 2*pi

contains

    subroutine run_elastic_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call unused(exe)   ! every suite is given the executable; this one needs none
        if (t%want('elastic: conversions and Newton-Euler against the paper''s equations')) &
            call test_conversions(t)
        if (t%want('elastic: energy conserved without damping')) call test_energy(t)
        if (t%want('elastic: converges to the paper''s model as 1/stiffness')) &
            call test_convergence(t)
        if (t%want('elastic: stiff cables switch LSODA to BDF')) call test_stiff(t)
        if (t%want('elastic: slack cables')) call test_slack(t)
        if (t%want('elastic: cable modes reproduce the law decided at each evaluation')) &
            call test_modes(t)
    end subroutine run_elastic_tests

    ! ---------------------------------------------------------------------------------------
    !> The paper's raised start (45 degrees, from rest) as a chart state.
    function raised_start(p) result(yc)
        type(pendulum_t), intent(in) :: p
        real(dp) :: yc(10), th(5)
        type(status_t) :: st
        call raised_angles(p, 45.0_dp*deg, th, st)
        call solve_theta5(p, th, st)
        yc = chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp])
    end function raised_start

    !> Angles and rates: the elastic state built from them gives them back; its energy
    !! (unstretched cables) is the paper model's; with the paper's tensions in the springs
    !! (elastic_start) Newton-Euler gives the paper's accelerations of R* and the body's
    !! angular acceleration, eq. (38) checked from outside.
    subroutine test_conversions(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el
        type(motion_t) :: mp, me
        type(status_t) :: st
        real(dp) :: th(5), thd(5), beta(5), y(ELASTIC_NSTATE), yc(10), eth, ethd, een, ea, eal
        real(dp) :: et
        integer :: trial
        el%p = cylinder(1.8_dp)
        el%p%lambda = 0.6_dp
        el%p%r = 0.8_dp
        el%p%btilde = reshape([0.8_dp, 0.6_dp, 0.0_dp, -0.6_dp, 0.8_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                               1.0_dp], [3, 3])
        el%p%inertia = [0.1_dp, 0.15_dp, 0.2_dp]
        el%stiffness = 1.0e5_dp
        eth = 0; ethd = 0; een = 0; ea = 0; eal = 0; et = 0
        do trial = 1, 4
            th = [0.1_dp*trial - 0.2_dp, 0.05_dp + 0.1_dp*trial, 0.3_dp + 1.4_dp*trial, &
                  0.4_dp - 0.25_dp*trial, 0.0_dp]
            call solve_theta5(el%p, th, st)
            call t%check('conversions: theta5 solves', st%code == 0)
            thd(1:4) = [0.2_dp, -0.1_dp, 0.3_dp, -0.25_dp]*(0.5_dp + 0.2_dp*trial)
            beta = beta_coeffs(el%p, th)
            thd(5) = sum(beta(1:4)*thd(1:4))/beta(5)
            ! round trip angles -> elastic -> angles, plain lengths
            el%l0 = -1.0_dp
            y = elastic_from_angles(el%p, th, thd)
            call elastic_evaluate(el, y, th(3), me, st)
            eth = max(eth, maxval(abs(me%th - th)))
            ethd = max(ethd, maxval(abs(me%thd - thd)))
            yc = chart_state(th, thd)
            een = max(een, abs(elastic_energy(el, y) - chart_energy(el%p, yc)))
            ! Newton-Euler with the paper's tensions
            call elastic_start(el, yc, y, st)
            call t%check('conversions: elastic_start', st%code == 0)
            call evaluate(el%p, yc, th(3), mp, st)
            call elastic_evaluate(el, y, th(3), me, st)
            call t%check('conversions: paper''s tensions positive', min(mp%t_bc, mp%t_ad) > 0)
            ea = max(ea, maxval(abs(me%astar - mp%astar)))
            eal = max(eal, maxval(abs(me%alpha - mp%alpha)))
            et = max(et, abs(me%t_bc - mp%t_bc), abs(me%t_ad - mp%t_ad))
        end do
        write (*, '(a,5es10.2)') '  round trip th, thd, energy; Newton-Euler a*, alpha: ', &
            eth, ethd, een, ea, eal
        call t%check_close('angles -> elastic -> angles', eth, 0.0_dp, atol=1.0e-12_dp)
        call t%check_close('rates -> elastic -> rates', ethd, 0.0_dp, atol=1.0e-12_dp)
        call t%check_close('energy of the elastic state = paper model''s', een, 0.0_dp, &
                           atol=1.0e-13_dp)
        call t%check_close('springs carry the paper''s tensions at the start', et, 0.0_dp, &
                           atol=1.0e-10_dp)
        call t%check_close('Newton: a of R* = paper''s eq. (38)', ea, 0.0_dp, atol=1.0e-10_dp)
        call t%check_close('Euler: alpha = paper''s eq. (38)', eal, 0.0_dp, atol=1.0e-10_dp)
    end subroutine test_conversions

    !> Without damping the total energy (kinetic + gravity + springs) is conserved.
    subroutine test_energy(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el
        type(elastic_solver_t) :: s
        type(integrator_stats_t) :: ss
        type(status_t) :: st
        real(dp) :: y(ELASTIC_NSTATE), e0, err, qn
        real(dp), parameter :: rtol = 1.0e-10_dp
        integer :: k
        el%p = cylinder(1.8_dp)
        el%stiffness = 1.0e4_dp
        el%damping = 0.0_dp
        call elastic_start(el, raised_start(el%p), y, st)
        e0 = elastic_energy(el, y)
        call s%init(el, 0.0_dp, y, rtol, [1.0e-12_dp], st)
        err = 0; qn = 0
        do k = 1, nint(3*TORSION_PERIOD/0.1_dp)
            call s%integrate(el, 0.1_dp*k, y, st)
            if (st%code /= 0) exit
            err = max(err, abs(elastic_energy(el, y) - e0))
            qn = max(qn, abs(norm2(y(7:10)) - 1.0_dp))
        end do
        ss = s%stats()
        write (*, '(a,es10.2,a,i0,a,es10.2)') '  k = 1e4: max |energy error| ', err, &
            ', steps ', ss%steps, ', max ||q| - 1| ', qn
        call t%check('energy run integrates 3 torsional periods', st%code == 0)
        call t%check_close('energy conserved without damping (10 rtol)', err, 0.0_dp, &
                           atol=10*rtol)
        call t%check_close('quaternion stays unit', qn, 0.0_dp, atol=10*rtol)
    end subroutine test_energy

    !> theta1, theta4 and Q approach the inextensible solution over three torsional periods
    !! as the stiffness grows, the difference shrinking like 1/stiffness.
    subroutine test_convergence(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: nk = 6
        real(dp), parameter :: dtau = 0.1_dp
        real(dp), parameter :: kk(nk) = [1.0e3_dp, 1.0e4_dp, 1.0e5_dp, 1.0e6_dp, 1.0e7_dp, 1.0e8_dp]
        type(bifilar_t) :: sys
        type(elastic_t) :: el
        type(lsoda_t) :: s
        type(elastic_solver_t) :: es
        type(status_t) :: st
        type(motion_t) :: mo
        real(dp), allocatable :: ref(:, :)
        real(dp) :: yc(10), y(ELASTIC_NSTATE), th3, diff(3, nk), slope(3), thr(5)
        type(integrator_stats_t) :: ss
        integer :: nout, k, j
        logical :: ok
        character(len=*), parameter :: names(3) = ['theta1', 'theta4', 'Q     ']
        nout = nint(3*TORSION_PERIOD/dtau)
        allocate (ref(3, 0:nout))
        sys%p = cylinder(1.8_dp)
        sys%p%stab_rate = 1.0_dp
        yc = raised_start(sys%p)
        call s%init(sys, 0.0_dp, yc, 1.0e-12_dp, [1.0e-14_dp], st)
        th3 = 0
        ok = .true.
        do k = 0, nout
            if (k > 0) call s%integrate(sys, dtau*k, yc, st)
            ok = ok .and. st%code == 0
            call evaluate(sys%p, yc, th3, mo, st)
            th3 = mo%th(3)
            ref(:, k) = [mo%th(1), mo%th(4), mo%q_sway]
        end do
        call t%check('inextensible reference integrates', ok)
        do j = 1, nk
            el%p = sys%p
            el%stiffness = kk(j)
            el%damping = 0.05_dp
            call elastic_start(el, raised_start(el%p), y, st)
            call es%init(el, 0.0_dp, y, 1.0e-12_dp, elastic_atol(el, 1.0e-14_dp, 1.0e-12_dp), &
                         st)
            thr = 0
            diff(:, j) = 0
            do k = 0, nout
                if (k > 0) call es%integrate(el, dtau*k, y, st)
                ok = ok .and. st%code == 0
                call elastic_evaluate(el, y, thr(3), mo, st, thr)
                thr = mo%th
                diff(:, j) = max(diff(:, j), abs([mo%th(1), mo%th(4), mo%q_sway] - ref(:, k)))
            end do
            ss = es%stats()
            write (*, '(a,es8.1,a,3es10.2,a,i0,a,i0)') '  k = ', kk(j), &
                ': max |diff| theta1, theta4, Q ', diff(:, j), '  steps ', ss%steps, &
                '  switches ', ss%method_switches
        end do
        call t%check('elastic runs integrate', ok)
        ! least-squares slope of log(diff) against log(k) over 1e3..1e7 (where the
        ! difference is well above the integration error, rtol 1e-12)
        do j = 1, 3
            slope(j) = fit_slope(log10(kk(1:5)), log10(diff(j, 1:5)))
            write (*, '(a,f7.3)') '  slope '//trim(names(j))//' (1e3 ... 1e7): ', slope(j)
            call t%check('difference in '//trim(names(j))//' shrinks like 1/stiffness '// &
                         '(slope in [-1.1, -0.9])', slope(j) > -1.1_dp .and. slope(j) < -0.9_dp)
            ! at 1e8 the integration error floors the difference near 1e-8 ... 1e-7
            call t%check(trim(names(j))//': k = 1e8 closer than k = 1e6 / 5', &
                         diff(j, 6) < 0.2_dp*diff(j, 4))
        end do
    end subroutine test_convergence

    pure real(dp) function fit_slope(x, y) result(b)
        real(dp), intent(in) :: x(:), y(:)
        real(dp) :: xm, ym
        xm = sum(x)/size(x)
        ym = sum(y)/size(y)
        b = sum((x - xm)*(y - ym))/sum((x - xm)**2)
    end function fit_slope

    !> At stiffness 1e6 and 1e8 with damping (zeta = 0.5) LSODA with the cables' modes
    !! (elastic_solver) switches to BDF and takes far fewer steps than an explicit method
    !! would need for stability alone (classical RK4: |h lambda| <= 2.8 on the imaginary axis,
    !! less elsewhere; lambda the largest eigenvalue of the Jacobian at the start): more than
    !! 5 times fewer at 1e6, 100 times fewer at 1e8.  The explicit bound grows like
    !! sqrt(k); LSODA's steps do not grow from 1e6 to 1e8.  At 1e6 the same LSODA kept in
    !! Adams (the non-stiff method with error control) takes more than 10 times the steps.
    subroutine test_stiff(t)
        type(tester_t), intent(inout) :: t
        real(dp), parameter :: kk(2) = [1.0e6_dp, 1.0e8_dp]
        type(elastic_t) :: el
        type(elastic_solver_t) :: s
        type(status_t) :: st
        type(integrator_stats_t) :: ss, sa
        real(dp) :: y(ELASTIC_NSTATE), jac(ELASTIC_NSTATE, ELASTIC_NSTATE), f0(ELASTIC_NSTATE)
        real(dp) :: fp(ELASTIC_NSTATE), fm(ELASTIC_NSTATE), yp(ELASTIC_NSTATE), h, rho, tend
        real(dp) :: rk4_steps(2)
        real(dp), parameter :: gain(2) = [5.0_dp, 100.0_dp]
        complex(dp) :: lam(ELASTIC_NSTATE)
        integer :: j, i, steps(2)
        character(len=8) :: tag
        do i = 1, size(kk)
            write (tag, '(a,i0)') 'k = 1e', nint(log10(kk(i)))
            el%p = cylinder(1.8_dp)
            el%stiffness = kk(i)
            el%damping = 0.5_dp
            el%l0 = -1.0_dp
            el%mode = CABLE_AUTO
            call elastic_start(el, raised_start(el%p), y, st)
            call el%rhs(0.0_dp, y, f0, st)
            do j = 1, ELASTIC_NSTATE
                h = 1.0e-7_dp*max(1.0_dp, abs(y(j)))
                yp = y
                yp(j) = y(j) + h
                call el%rhs(0.0_dp, yp, fp, st)
                yp(j) = y(j) - h
                call el%rhs(0.0_dp, yp, fm, st)
                jac(:, j) = (fp - fm)/(2*h)
            end do
            call la_eig(jac, lam, st)
            rho = maxval(abs(lam))
            tend = 3*TORSION_PERIOD
            rk4_steps(i) = tend*rho/2.8_dp
            call s%init(el, 0.0_dp, y, 1.0e-8_dp, elastic_atol(el, 1.0e-10_dp, 1.0e-8_dp), st, &
                        method=SOLVER_LSODA)
            call s%integrate(el, tend, y, st)
            ss = s%stats()
            write (*, '(a,es10.3,a,f10.0,a,i0,a,i0,a,i0,a,i0,a,i0)') '  '//trim(tag)// &
                ', zeta 0.5, rtol 1e-8: spectral radius ', rho, ', RK4 stable steps >= ', &
                rk4_steps(i), '; LSODA steps ', ss%steps, ', rhs ', ss%rhs_evals, ', jac ', &
                ss%jac_evals, ', convergence failures ', ss%conv_failures, ', cable switches ', &
                s%switches()
            call t%check(trim(tag)//': stiff run integrates 3 torsional periods', st%code == 0)
            call t%check(trim(tag)//': spectral radius ~ sqrt(k)', &
                         rho > sqrt(el%stiffness/el%p%big_l))
            call t%check(trim(tag)//': LSODA switched to BDF', ss%method_switches >= 1 .and. &
                         ss%method_last == METHOD_BDF)
            call t%check(trim(tag)//': LSODA steps < RK4 stable steps / '//itoa(nint(gain(i))), &
                         gain(i)*ss%steps < rk4_steps(i))
            steps(i) = ss%steps
            call t%check(trim(tag)//': no cable went slack', s%switches() == 0 .and. &
                         all(el%mode == CABLE_TAUT))
            if (i == 1) then
                ! the non-stiff method with error control: the same LSODA kept in Adams
                call elastic_start(el, raised_start(el%p), y, st)
                call s%init(el, 0.0_dp, y, 1.0e-8_dp, elastic_atol(el, 1.0e-10_dp, 1.0e-8_dp), &
                            st, nonstiff_only=.true.)
                call s%integrate(el, tend, y, st, max_steps=2000000)
                sa = s%stats()
                write (*, '(a,i0)') '  k = 1e6, Adams only (non-stiff): steps ', sa%steps
                call t%check('k = 1e6: Adams alone (non-stiff) takes > 10 times the steps', &
                             st%code == 0 .and. sa%steps > 10*ss%steps .and. &
                             sa%method_switches == 0)
            end if
        end do
        call t%check('LSODA steps do not grow from k = 1e6 to 1e8 (the RK4 bound grows > 10x)', &
                     steps(2) <= steps(1) .and. rk4_steps(2) > 10*rk4_steps(1))
    end subroutine test_stiff

    !> The rest pose of the paper's model with l' = 1.8 (theta5 from eq. (2)), cables at their
    !! natural lengths, thrown upwards with speed v0.
    function thrown(el, v0) result(y)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: v0
        real(dp) :: y(ELASTIC_NSTATE), th(5)
        type(status_t) :: st
        th = 0
        call solve_theta5(el%p, th, st)
        y = elastic_from_angles(el%p, th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp])
        y(6) = v0
    end function thrown

    !> Thrown upwards from the rest-length pose, the body flies free: both cables slack
    !! (tension 0) for exactly 2 v0 (pure translation under gravity), the run continues
    !! through the slack interval and the re-tensioning, and without damping the energy is
    !! conserved throughout.  The switches are located to roundoff (elastic_solver): the
    !! first slack interval of each cable is [0, 2 v0] to 1e-7, and the slack times and
    !! interval counts agree with the list of intervals.
    subroutine test_slack(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el, ea
        type(elastic_solver_t) :: s
        type(status_t) :: st
        type(motion_t) :: mo, mo_auto
        type(elastic_cables_t) :: cab, cab_auto
        type(slack_interval_t), allocatable :: list(:)
        real(dp), parameter :: v0 = 1.0_dp, dtau = 0.005_dp, rtol = 1.0e-10_dp, tend = 8.0_dp
        real(dp) :: y(ELASTIC_NSTATE), e0, err, thr(5), tsum(2), first(2, 2)
        logical :: zero_when_slack, ok
        integer :: k, j, i, nlist(2)
        type(integrator_stats_t) :: ss
        el%p = cylinder(1.8_dp)
        el%stiffness = 1.0e4_dp
        el%damping = 0.0_dp
        el%l0 = -1.0_dp                  ! the deck's lengths unstretched: T = 0 at the start
        y = thrown(el, v0)
        e0 = elastic_energy(el, y)
        call s%init(el, 0.0_dp, y, rtol, [1.0e-12_dp], st)
        err = 0
        thr = 0
        zero_when_slack = .true.
        ok = st%code == 0
        do k = 1, nint(tend/dtau)
            call s%integrate(el, dtau*k, y, st)
            ok = ok .and. st%code == 0
            if (st%code /= 0) exit
            call elastic_evaluate(el, y, thr(3), mo, st, thr, cab)
            thr = mo%th
            err = max(err, abs(mo%energy - e0))
            ! the tensions reported in the modes are the law's (decided at each evaluation):
            ! 0 where it has the cable slack, the same spring force where taut
            ea = el
            ea%mode = CABLE_AUTO
            call elastic_evaluate(ea, y, thr(3), mo_auto, st, thr, cab_auto)
            zero_when_slack = zero_when_slack .and. all(abs(cab%tension - cab_auto%tension) &
                              <= 1.0e-9_dp) .and. all(cab%slack .eqv. cab_auto%slack) .and. &
                              mo%t_bc == cab%tension(CABLE_BC) .and. &
                              mo%t_ad == cab%tension(CABLE_AD)
        end do
        allocate (list, source=s%slack_list())
        ss = s%stats()
        first = -1
        tsum = 0
        nlist = 0
        do i = 1, size(list)
            j = list(i)%cable
            nlist(j) = nlist(j) + 1
            if (first(1, j) < 0) first(:, j) = [list(i)%tau_start, list(i)%tau_end]
            if (.not. list(i)%open) then
                tsum(j) = tsum(j) + (list(i)%tau_end - list(i)%tau_start)
            else
                tsum(j) = tsum(j) + (ss%t_current - list(i)%tau_start)
            end if
        end do
        write (*, '(a,2es12.4,a,2es12.4,a,2i3,a,2f8.4,a,es10.2,a,i0,a,i0)') &
            '  first slack interval BC ', first(:, 1), ', AD ', first(:, 2), &
            '; slack intervals ', s%slack_intervals(), '; slack time ', s%slack_time(), &
            '; max |energy error| ', err, '; steps ', ss%steps, '; cable switches ', &
            s%switches()
        call t%check('slack run integrates', ok)
        do j = 1, 2
            call t%check_close(trim(merge('BC', 'AD', j == 1))//' slack from the start', &
                               first(1, j), 0.0_dp, atol=1.0e-7_dp)
            call t%check_close(trim(merge('BC', 'AD', j == 1))//' taut again after 2 v0 '// &
                               '(free flight)', first(2, j), 2*v0, atol=1.0e-7_dp)
        end do
        call t%check('slack intervals counted as listed', all(s%slack_intervals() == nlist) &
                     .and. all(nlist >= 2))
        call t%check('slack time is the sum of the listed intervals', &
                     all(abs(s%slack_time() - tsum) <= 1.0e-9_dp*tend))
        call t%check('tensions and slack flags are the law''s at every row (0 while slack)', &
                     zero_when_slack)
        call t%check_close('energy conserved through slack and snap (100 rtol)', err, 0.0_dp, &
                           atol=100*rtol)
        call t%check('natural lengths are the deck''s', all(natural_lengths(el) == &
                     [el%p%big_l, el%p%big_lp]))
    end subroutine test_slack

    !> With damping the modes (taut: smooth spring-dashpot, slack: no force; switches located
    !! in the dense output) give the motion of the law decided at each evaluation: a thrown
    !! body with damping 0.2 bounces on its cables; LSODA with modes and plain LSODA on the
    !! law with its kinks agree at rtol 1e-10.  The modes always agree with the law's
    !! switching function at the step ends, and a taut cable is never left with g < 0.
    subroutine test_modes(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el, ea
        type(elastic_solver_t) :: s
        type(lsoda_t) :: sa
        type(status_t) :: st, sta
        type(integrator_stats_t) :: ss, sa_st
        real(dp), parameter :: rtol = 1.0e-10_dp, tend = 6.0_dp
        real(dp) :: y(ELASTIC_NSTATE), ya(ELASTIC_NSTATE), diff, g(2)
        logical :: agree_modes
        integer :: n
        el%p = cylinder(1.8_dp)
        el%stiffness = 1.0e4_dp
        el%damping = 0.2_dp
        el%l0 = -1.0_dp
        ea = el
        ea%mode = CABLE_AUTO
        y = thrown(el, 0.5_dp)
        ya = y
        call s%init(el, 0.0_dp, y, rtol, [1.0e-12_dp], st)
        agree_modes = .true.
        n = 0
        do while (st%code == 0)
            ss = s%stats()
            if (ss%t_current >= tend) exit
            call s%step(el, st, tend)
            if (st%code /= 0) exit
            ss = s%stats()
            call s%dense(ss%t_current, 0, y, st)
            g = cable_switch(el, y)
            ! at a step end the mode in force is taut where g > 0 (a switch ends the step at
            ! the first point with the new sign, so the old mode is one roundoff behind)
            if (s%switches() == n) agree_modes = agree_modes .and. &
                all((el%mode == CABLE_TAUT) .eqv. (g > 0.0_dp))
            n = s%switches()
        end do
        call s%integrate(el, tend, y, st)
        call sa%init(ea, 0.0_dp, ya, rtol, [1.0e-12_dp], sta, tcrit=tend)
        call sa%integrate(ea, tend, ya, sta)
        sa_st = sa%stats()
        diff = maxval(abs(y(1:3) - ya(1:3)))
        write (*, '(a,i0,a,es10.2,a,i0,a,i0)') '  damping 0.2: cable switches ', s%switches(), &
            ', max |R* difference| from the law with kinks ', diff, '; steps with modes ', &
            ss%steps, ', without ', sa_st%steps
        call t%check('modes run and plain run integrate', st%code == 0 .and. sta%code == 0)
        call t%check('the cables switch several times', s%switches() >= 4)
        call t%check('modes agree with the switching function at step ends', agree_modes)
        call t%check_close('same motion as the law with kinks (1e-6)', diff, 0.0_dp, &
                           atol=1.0e-6_dp)
    end subroutine test_modes

end module test_elastic
