!> Tests of the analytic Jacobian of the elastic-cable model (elastic_model
!! elastic_jacobian): against central differences of elastic_rhs at general states (rotated
!! anisotropic body, moving, spinning, |q| /= 1) in every cable mode, stiffness 1e4 and 1e8,
!! damping 0 and 0.5; that the comparison catches a missing term; the homogeneity of R in q;
!! and an LSODA run with the analytic Jacobian against one with finite differences.
module test_elastic_jac
    use kinds, only: dp, pi
    use status, only: status_t
    use testing, only: tester_t
    use test_model, only: cylinder
    use geometry, only: pendulum_t, beta_coeffs
    use start_pose, only: solve_theta5, raised_angles
    use bifilar_model, only: motion_t, chart_state
    use ode_system, only: ode_system_t, integrator_stats_t
    use elastic_model, only: elastic_t, elastic_cables_t, elastic_from_angles, elastic_start, &
                             elastic_evaluate, elastic_atol, elastic_pose, ELASTIC_NSTATE, &
                             CABLE_AUTO, CABLE_TAUT, CABLE_SLACK
    use lsoda, only: lsoda_t
    use unused_arg, only: unused
    implicit none
    private

    public :: run_elastic_jac_tests

    integer, parameter :: N = ELASTIC_NSTATE
    !> Agreement required of the analytic and the finite-difference Jacobian: relative to the
    !! column's scale within each block of rows (R*, v*, q, omega).
    real(dp), parameter :: JAC_TOL = 1.0e-6_dp

    !> The elastic model with the analytic Jacobian switched off: LSODA differences it.
    type, extends(elastic_t) :: elastic_fd_t
    contains
        procedure :: has_jacobian => fd_has_jacobian
    end type elastic_fd_t

contains

    subroutine run_elastic_jac_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call unused(exe)   ! every suite is given the executable; this one needs none
        if (t%want('elastic jacobian: analytic = central differences, every mode')) &
            call test_against_fd(t)
        if (t%want('elastic jacobian: the comparison catches a wrong Jacobian')) &
            call test_detects_errors(t)
        if (t%want('elastic jacobian: structure (has_jacobian, q homogeneity, zero q)')) &
            call test_structure(t)
        if (t%want('elastic jacobian: LSODA with the analytic Jacobian')) call test_lsoda_run(t)
    end subroutine run_elastic_jac_tests

    logical function fd_has_jacobian(sys)
        class(elastic_fd_t), intent(in) :: sys
        call unused(sys)
        fd_has_jacobian = .false.
    end function fd_has_jacobian

    ! ---------------------------------------------------------------------------------------
    !> A general rigid body on the cylinder deck's cables: R* off the CD line, principal axes
    !! rotated, three different moments (so no term of Euler's equations vanishes).
    function general_body() result(p)
        type(pendulum_t) :: p
        p = cylinder(1.8_dp)
        p%lambda = 0.6_dp
        p%r = 0.8_dp
        p%btilde = reshape([0.8_dp, 0.6_dp, 0.0_dp, -0.6_dp, 0.8_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                            1.0_dp], [3, 3])
        p%inertia = [0.1_dp, 0.15_dp, 0.2_dp]
    end function general_body

    !> Test state `trial` (1..3): a pose of the paper's model with rates, then an extra
    !! velocity of R* and angular velocity (the cables stretch and turn), |q| = 1 + 0.02 trial
    !! (or 1 - 0.03 for trial 2).
    function general_state(p, trial) result(y)
        type(pendulum_t), intent(in) :: p
        integer, intent(in) :: trial
        real(dp) :: y(N), th(5), thd(5), beta(5)
        type(status_t) :: st
        th = [0.1_dp*trial - 0.2_dp, 0.05_dp + 0.1_dp*trial, 0.3_dp + 1.4_dp*trial, &
              0.4_dp - 0.25_dp*trial, 0.0_dp]
        call solve_theta5(p, th, st)
        thd(1:4) = [0.2_dp, -0.1_dp, 0.3_dp, -0.25_dp]*(0.5_dp + 0.2_dp*trial)
        beta = beta_coeffs(p, th)
        thd(5) = sum(beta(1:4)*thd(1:4))/beta(5)
        y = elastic_from_angles(p, th, thd)
        y(4:6) = y(4:6) + [0.11_dp, -0.07_dp, 0.05_dp]*trial
        y(11:13) = y(11:13) + [0.3_dp, -0.45_dp, 0.25_dp]/trial
        if (trial == 2) then
            y(7:10) = 0.97_dp*y(7:10)
        else
            y(7:10) = (1.0_dp + 0.02_dp*trial)*y(7:10)
        end if
    end function general_state

    !> Cable lengths and rates of change at y.
    subroutine cable_lengths(el, y, length, rate)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(N)
        real(dp), intent(out) :: length(2), rate(2)
        type(motion_t) :: mo
        type(status_t) :: st
        type(elastic_cables_t) :: cab
        call elastic_evaluate(el, y, 0.0_dp, mo, st, cab=cab)
        length = cab%length
        rate = cab%length_rate
    end subroutine cable_lengths

    !> Central differences of el%rhs at y: step 1e-6 max(1, |y_j|) in the positions and the
    !! quaternion, 1e-3 max(1, |y_j|) in the velocities and angular velocities (ydot is a
    !! quadratic polynomial in those, so central differences have no truncation error there
    !! and a long step only cuts rounding).  In the positions at k = 1e8 the rounding error
    !! of the spring force, ~ k 1e-16 over the step, is ~ 1e-10 of the column's scale k, the
    !! truncation error ~ h^2 relative.
    function fd_jacobian(el, y) result(jac)
        class(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y(N)
        real(dp) :: jac(N, N), yp(N), fp(N), fm(N), h
        type(status_t) :: st
        integer :: j
        do j = 1, N
            if (j <= 3 .or. (j >= 7 .and. j <= 10)) then
                h = 1.0e-6_dp*max(1.0_dp, abs(y(j)))
            else
                h = 1.0e-3_dp*max(1.0_dp, abs(y(j)))
            end if
            yp = y
            yp(j) = y(j) + h
            h = yp(j) - y(j)
            call el%rhs(0.0_dp, yp, fp, st)
            yp(j) = y(j) - h
            call el%rhs(0.0_dp, yp, fm, st)
            jac(:, j) = (fp - fm)/(2*h)
        end do
    end function fd_jacobian

    !> max over entries of |a - b| relative to the scale of the column of `b` within the
    !! entry's block of rows (R*' 1:3, v*' 4:6, q' 7:10, omega' 11:13), floored at 1.
    pure real(dp) function jac_error(a, b) result(err)
        real(dp), intent(in) :: a(N, N), b(N, N)
        integer, parameter :: lo(4) = [1, 4, 7, 11], hi(4) = [3, 6, 10, 13]
        integer :: j, k
        err = 0.0_dp
        do j = 1, N
            do k = 1, 4
                err = max(err, maxval(abs(a(lo(k):hi(k), j) - b(lo(k):hi(k), j)))/ &
                      max(1.0_dp, maxval(abs(b(lo(k):hi(k), j)))))
            end do
        end do
    end function jac_error

    !> Relative disagreement of the analytic and the finite-difference Jacobian at y.
    real(dp) function disagreement(el, y) result(err)
        type(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y(N)
        real(dp) :: jan(N, N), jfd(N, N)
        type(status_t) :: st
        call el%jacobian(0.0_dp, y, jan, st)
        jfd = fd_jacobian(el, y)
        err = jac_error(jfd, jan)
        if (st%code /= 0) err = huge(1.0_dp)
    end function disagreement

    ! ---------------------------------------------------------------------------------------
    !> Every mode combination, both stiffnesses and damping ratios, three states each.  The
    !! natural lengths are set from the state so each cable is in the intended branch
    !! (checked), far from the kink compared with what the finite-difference steps change
    !! (k 1e-6/L0 and c 1e-3): stretched (eps = 1e-5 + (100 + 2 c |rate|)/k), compressed
    !! (eps = -1e-5 - 10/k, where CABLE_TAUT pushes), or (CABLE_AUTO, damped) shortening at
    !! rate 0.2 and stretched by half what the dashpot takes away, so the clipped law gives
    !! T = 0 with eps > 0.
    subroutine test_against_fd(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: ncase = 7
        ! per case: modes of BC and AD, and the strain kind of each (1 stretched,
        ! 2 compressed, 3 clipped by the dashpot)
        integer, parameter :: modes(2, ncase) = reshape([CABLE_TAUT, CABLE_TAUT, &
            CABLE_TAUT, CABLE_TAUT, CABLE_TAUT, CABLE_SLACK, CABLE_SLACK, CABLE_TAUT, &
            CABLE_AUTO, CABLE_AUTO, CABLE_AUTO, CABLE_AUTO, CABLE_AUTO, CABLE_AUTO], [2, ncase])
        integer, parameter :: skind(2, ncase) = reshape([1, 1, 1, 2, 1, 1, 1, 1, 1, 1, 1, 2, &
                                                        3, 1], [2, ncase])
        character(len=*), parameter :: names(ncase) = [character(len=30) :: &
            'TAUT/TAUT stretched', 'TAUT/TAUT, AD compressed', 'TAUT/SLACK', 'SLACK/TAUT', &
            'AUTO/AUTO stretched', 'AUTO, AD slack (eps < 0)', 'AUTO, BC clipped by dashpot']
        real(dp), parameter :: kk(2) = [1.0e4_dp, 1.0e8_dp], zz(2) = [0.0_dp, 0.5_dp]
        type(elastic_t) :: el
        type(status_t) :: st
        type(motion_t) :: mo
        type(elastic_cables_t) :: cab
        real(dp) :: y(N), length(2), rate(2), strain(2), err, worst, c
        integer :: ic, ik, iz, trial, j
        logical :: branch_ok
        character(len=80) :: label
        worst = 0
        do ic = 1, ncase
            do ik = 1, 2
                do iz = 1, 2
                    if (any(skind(:, ic) == 3) .and. zz(iz) == 0.0_dp) cycle  ! needs a dashpot
                    err = 0
                    branch_ok = .true.
                    do trial = 1, 3
                        el = elastic_t()
                        el%p = general_body()
                        el%stiffness = kk(ik)
                        el%damping = zz(iz)
                        el%mode = modes(:, ic)
                        y = general_state(el%p, trial)
                        call cable_lengths(el, y, length, rate)
                        do j = 1, 2
                            c = 2*el%damping*sqrt(el%stiffness/length(j))
                            select case (skind(j, ic))
                            case (1)
                                strain(j) = 1.0e-5_dp + (100 + 2*c*abs(rate(j)))/el%stiffness
                            case (2)
                                strain(j) = -1.0e-5_dp - 10/el%stiffness
                            case default
                                ! shortening at rate -0.2, k eps = -c rate/2
                                y(4:6) = y(4:6) - (rate(j) + 0.2_dp)*cable_axis(el, y, j)
                                call cable_lengths(el, y, length, rate)
                                strain(j) = -0.5_dp*c*rate(j)/el%stiffness
                            end select
                        end do
                        el%l0 = length/(1.0_dp + strain)
                        ! the intended branch of the law: AUTO cables as the modes say
                        call elastic_evaluate(el, y, 0.0_dp, mo, st, cab=cab)
                        do j = 1, 2
                            if (modes(j, ic) /= CABLE_AUTO) cycle
                            branch_ok = branch_ok .and. (cab%slack(j) .eqv. skind(j, ic) /= 1)
                            if (skind(j, ic) == 3) branch_ok = branch_ok .and. cab%strain(j) > 0
                        end do
                        err = max(err, disagreement(el, y))
                    end do
                    worst = max(worst, err)
                    write (label, '(a,a,es7.0,a,f3.1)') trim(names(ic)), ', k ', kk(ik), &
                        ', zeta ', zz(iz)
                    write (*, '(2x,a,a,es9.2)') label(1:48), ' max rel. |J - J_fd| ', err
                    call t%check('state in the intended branch: '//trim(label), branch_ok)
                    call t%check_close('J = J_fd: '//trim(label), err, 0.0_dp, atol=JAC_TOL)
                end do
            end do
        end do
        write (*, '(a,es9.2)') '  worst relative disagreement ', worst
    end subroutine test_against_fd

    !> Unit vector from the support to the body point of cable j at y.
    function cable_axis(el, y, j) result(u)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(N)
        integer, intent(in) :: j
        real(dp) :: u(3), c(3), d(3), e(3), vc(3), vd(3), n(3, 3), omega(3)
        call elastic_pose(el%p, y, c, d, e, vc, vd, n, omega)
        if (j == 1) then
            u = c - [0.0_dp, -el%p%big_b, 0.0_dp]
        else
            u = d
        end if
        u = u/norm2(u)
    end function cable_axis

    !> The comparison is sharp: a Jacobian of a slightly different system is rejected - no
    !! quaternion stabilisation, a cable's mode changed, a damping ratio off by 1e-4 - while
    !! the finite differences of the true system stay the reference.
    subroutine test_detects_errors(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el, wrong
        type(status_t) :: st
        real(dp) :: y(N), length(2), rate(2), jan(N, N), jfd(N, N), e1, e2, e3
        el%p = general_body()
        el%stiffness = 1.0e4_dp
        el%damping = 0.5_dp
        el%mode = CABLE_TAUT
        y = general_state(el%p, 1)
        call cable_lengths(el, y, length, rate)
        el%l0 = length/1.01_dp
        jfd = fd_jacobian(el, y)
        wrong = el
        wrong%quat_rate = 0.0_dp
        call wrong%jacobian(0.0_dp, y, jan, st)
        e1 = jac_error(jfd, jan)
        wrong = el
        wrong%mode(2) = CABLE_SLACK
        call wrong%jacobian(0.0_dp, y, jan, st)
        e2 = jac_error(jfd, jan)
        wrong = el
        wrong%damping = el%damping*(1.0_dp + 1.0e-4_dp)
        call wrong%jacobian(0.0_dp, y, jan, st)
        e3 = jac_error(jfd, jan)
        write (*, '(a,3es9.2)') '  rel. disagreement without stabilisation, AD slack, '// &
            'damping + 1e-4: ', e1, e2, e3
        call t%check('no quaternion stabilisation is caught', e1 > 100*JAC_TOL)
        call t%check('a wrong cable mode is caught', e2 > 100*JAC_TOL)
        call t%check('damping off by 1e-4 is caught', e3 > JAC_TOL)
    end subroutine test_detects_errors

    !> has_jacobian through the parent type; the force and torque rows do not depend on |q|
    !! (sum_k q_k dydot/dq_k = 0 there: R is built from q/|q|); a zero quaternion is an
    !! error, as in elastic_rhs.
    subroutine test_structure(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t), target :: el
        class(ode_system_t), pointer :: sys
        type(status_t) :: st
        real(dp) :: y(N), length(2), rate(2), jan(N, N), hom(N), scale
        el%p = general_body()
        el%stiffness = 1.0e8_dp
        el%damping = 0.5_dp
        el%mode = CABLE_TAUT
        y = general_state(el%p, 3)
        call cable_lengths(el, y, length, rate)
        el%l0 = length/1.001_dp
        sys => el
        call t%check('has_jacobian is true for the elastic model', sys%has_jacobian())
        call sys%jacobian(0.0_dp, y, jan, st)
        call t%check('jacobian status ok', st%code == 0)
        hom = matmul(jan(:, 7:10), y(7:10))
        scale = maxval(abs(jan(4:6, 7:10)))
        write (*, '(a,2es9.2)') '  |sum_k q_k d(v*'', omega'')/dq_k| / scale: ', &
            maxval(abs(hom(4:6)))/scale, maxval(abs(hom(11:13)))/maxval(abs(jan(11:13, 7:10)))
        call t%check_close('force rows homogeneous of degree 0 in q', &
                           maxval(abs(hom(4:6)))/scale, 0.0_dp, atol=1.0e-12_dp)
        call t%check_close('torque rows homogeneous of degree 0 in q', &
                           maxval(abs(hom(11:13)))/maxval(abs(jan(11:13, 7:10))), 0.0_dp, &
                           atol=1.0e-12_dp)
        call t%check_close('position rows: d(R*'')/dv* = I', sum(abs(jan(1:3, :))), 3.0_dp, &
                           atol=0.0_dp)
        y(7:10) = 0.0_dp
        call sys%jacobian(0.0_dp, y, jan, st)
        call t%check('zero quaternion is an error', st%code /= 0)
    end subroutine test_structure

    !> The cylinder from the raised start at k = 1e8, zeta 0.5 (LSODA switches to BDF), tau
    !! 0..2 pi, rtol 1e-8: with the analytic Jacobian the run takes about the steps of the
    !! run with LSODA's finite-difference Jacobian (the iteration matrices agree), is as
    !! accurate (against a run at rtol 1e-11) and spends far fewer right-hand sides (not 13
    !! per Jacobian).
    subroutine test_lsoda_run(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el
        type(elastic_fd_t) :: elfd
        type(lsoda_t) :: s
        type(status_t) :: st, st2, st3
        type(integrator_stats_t) :: sa, sf
        real(dp) :: y0(N), ya(N), yf(N), yr(N), th(5), atol(N), ea, ef
        real(dp), parameter :: rtol = 1.0e-8_dp, tend = 2*pi
        el%p = cylinder(1.8_dp)
        el%stiffness = 1.0e8_dp
        el%damping = 0.5_dp
        el%mode = CABLE_TAUT
        call raised_angles(el%p, 0.7_dp, th, st)
        call solve_theta5(el%p, th, st)
        call elastic_start(el, chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]), y0, st)
        atol = elastic_atol(el, 1.0e-10_dp)
        elfd%elastic_t = el
        ya = y0
        call s%init(el, 0.0_dp, ya, rtol, atol, st)
        call s%integrate(el, tend, ya, st)
        sa = s%stats()
        yf = y0
        call s%init(elfd, 0.0_dp, yf, rtol, atol, st2)
        call s%integrate(elfd, tend, yf, st2)
        sf = s%stats()
        yr = y0
        call s%init(el, 0.0_dp, yr, 1.0e-3_dp*rtol, 1.0e-3_dp*atol, st3)
        call s%integrate(el, tend, yr, st3)
        ea = maxval(abs(ya - yr)/(atol + rtol*abs(yr)))
        ef = maxval(abs(yf - yr)/(atol + rtol*abs(yr)))
        write (*, '(a,3(i0,a),es9.2)') '  k = 1e8, zeta 0.5, tau 0..2 pi: analytic Jacobian ', &
            sa%steps, ' steps, ', sa%rhs_evals, ' rhs, ', sa%jac_evals, ' jac, error/tol ', ea
        write (*, '(a,3(i0,a),es9.2)') '                           finite differences ', &
            sf%steps, ' steps, ', sf%rhs_evals, ' rhs, ', sf%jac_evals, ' jac, error/tol ', ef
        call t%check('analytic-Jacobian run integrates', st%code == 0)
        call t%check('finite-difference run integrates', st2%code == 0)
        call t%check('reference run integrates', st3%code == 0)
        call t%check('the runs use Jacobians (BDF)', sa%jac_evals > 0 .and. sf%jac_evals > 0)
        call t%check('the runs take about the same steps (within 10 %)', &
                     abs(sa%steps - sf%steps) <= 0.1_dp*sf%steps)
        call t%check('analytic-Jacobian run as accurate as the other (error < 2x + 10 tol)', &
                     ea < 2*ef + 10)
        call t%check('analytic Jacobian saves right-hand sides (rhs < 0.5 x FD run''s)', &
                     sa%rhs_evals < 0.5_dp*sf%rhs_evals)
    end subroutine test_lsoda_run

end module test_elastic_jac
