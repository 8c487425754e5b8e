!> Tests of the elastic model's generalized coordinates (module elastic_gen) and of Radau IIA
!! on the elastic cables against the targets: the global error follows rtol over
!! stiffness and damping; lightly damped stiff cables in far fewer steps than CVODE needs
!! and fewer evaluations than LSODA at equal accuracy; no blow-up at tight tolerance.
!!
!! The stiff-cable scene: the Figs. 4-6 cylinder (l = 2 b', l' = 1.8 b'), raised 45 degrees,
!! tau = 0 ... 20, output every 0.05, atol = rtol/100; errors in theta1, theta4, theta5 and
!! Q against a reference (Radau, rtol 1e-13), itself confirmed by LSODA in the maximal
!! coordinates where that is affordable (make bench confirms every reference).
module test_elastic_radau
    use kinds, only: dp, deg
    use status, only: status_t, ERR_DECK
    use testing, only: tester_t, write_text, scratch_dir
    use test_model, only: cylinder
    use geometry, only: beta_coeffs
    use start_pose, only: raised_angles, solve_theta5
    use bifilar_model, only: motion_t, chart_state
    use elastic_model, only: elastic_t, elastic_start, elastic_evaluate, elastic_atol, &
                             elastic_from_angles, quat_to_matrix, natural_lengths, &
                             ELASTIC_NSTATE, CABLE_AUTO, CABLE_TAUT
    use elastic_gen, only: elastic_gen_t, gen_to_maximal, maximal_to_gen, chart_quality, &
                           GEN_NSTATE
    use elastic_solver, only: elastic_solver_t, SOLVER_LSODA, SOLVER_RADAU
    use deck, only: deck_t, read_deck
    use simulate, only: run_simulation, run_summary_t
    use ode_system, only: integrator_stats_t
    use unused_arg, only: unused
    implicit none
    private

    public :: run_elastic_radau_tests, issue_scene, scene_errors, solve_scene, NOUT, TEND

    !> The stiff-cable scene's interval and output grid.
    real(dp), parameter :: TEND = 20.0_dp, DTOUT = 0.05_dp
    integer, parameter :: NOUT = 400
    !> SUNDIALS CVODE 6.4.1 on the same equations: 37 791 steps for a theta1
    !! error of 2.5e-9 at k = 1e6, 318 366 steps for 1.3e-7 at k = 1e8 (damping 0.01).
    integer, parameter :: CVODE_STEPS_1E6 = 37791, CVODE_STEPS_1E8 = 318366
    real(dp), parameter :: CVODE_ERR_1E6 = 2.5e-9_dp, CVODE_ERR_1E8 = 1.3e-7_dp
    !> cylinder_l180_elastic's steps before this was mended (LSODA).
    integer, parameter :: STEPS_BEFORE = 58469

contains

    subroutine run_elastic_radau_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call unused(exe)   ! every suite is given the executable; this one needs none
        if (t%want('elastic radau: generalized coordinates against the maximal ones')) &
            call test_coordinates(t)
        if (t%want('elastic radau: global error follows rtol')) call test_follows(t)
        if (t%want('elastic radau: lightly damped stiff cables ahead of CVODE')) &
            call test_cvode(t)
        if (t%want('elastic radau: no blow-up')) call test_blowup(t)
        if (t%want('elastic radau: in and out of the generalized chart')) call test_recoords(t)
        if (t%want('elastic radau: &integration method chooses the integrator')) &
            call test_method_word(t)
    end subroutine run_elastic_radau_tests

    ! ---------------------------------------------------------------------------------------
    !> The stiff-cable scene at stiffness k and damping ratio zeta: the model and its start.
    subroutine issue_scene(k, zeta, el, y0)
        real(dp), intent(in) :: k, zeta
        type(elastic_t), intent(out) :: el
        real(dp), intent(out) :: y0(ELASTIC_NSTATE)
        real(dp) :: th(5)
        type(status_t) :: st
        el%p = cylinder(1.8_dp)
        el%stiffness = k
        el%damping = zeta
        call raised_angles(el%p, 45.0_dp*deg, th, st)
        call solve_theta5(el%p, th, st)
        call elastic_start(el, chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]), y0, st)
    end subroutine issue_scene

    !> The scene solved by `method` at rtol (atol = rtol/100; LSODA: elastic_atol's
    !! per-state tolerances), states at the NOUT + 1 output times; the counters; the CPU
    !! seconds of the solve (optional).
    subroutine solve_scene(el, y0, method, rtol, ys, st, stat, cpu, limits, recoords)
        type(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y0(:), rtol
        integer, intent(in) :: method
        real(dp), intent(out) :: ys(ELASTIC_NSTATE, 0:NOUT)
        type(integrator_stats_t), intent(out) :: st
        type(status_t), intent(out) :: stat
        real(dp), intent(out), optional :: cpu
        real(dp), intent(in), optional :: limits(2)     !! Radau: the chart's limits
        integer, intent(out), optional :: recoords      !! changes of coordinates
        type(elastic_solver_t) :: s
        real(dp) :: c0, c1
        integer :: k
        ys = 0.0_dp
        ys(:, 0) = y0
        call cpu_time(c0)
        if (present(limits)) then
            call s%init(el, 0.0_dp, y0, rtol, elastic_atol(el, rtol/100, rtol), stat, &
                        tcrit=TEND, method=method, chart_limits=limits)
        else
            call s%init(el, 0.0_dp, y0, rtol, elastic_atol(el, rtol/100, rtol), stat, &
                        tcrit=TEND, method=method)
        end if
        do k = 1, NOUT
            if (stat%code == 0) call s%integrate(el, k*DTOUT, ys(:, k), stat, max_steps=5000000)
        end do
        call cpu_time(c1)
        st = s%stats()
        if (present(cpu)) cpu = c1 - c0
        if (present(recoords)) recoords = s%recoords()
    end subroutine solve_scene

    !> The largest differences of theta1, theta4, theta5 (rad) and Q (b') between two
    !! solutions at the output times: err(1) over all four, err(2) theta1 alone.
    function scene_errors(el, ya, yb) result(err)
        type(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: ya(:, 0:), yb(:, 0:)
        real(dp) :: err(2)
        type(motion_t) :: ma, mb
        type(status_t) :: st
        real(dp) :: thr(5)
        integer :: k
        err = 0.0_dp
        el%mode = CABLE_AUTO
        call elastic_evaluate(el, yb(:, 0), 0.0_dp, mb, st)
        thr = mb%th
        do k = 0, ubound(ya, 2)
            call elastic_evaluate(el, yb(:, k), thr(3), mb, st, thr)
            call elastic_evaluate(el, ya(:, k), mb%th(3), ma, st, mb%th)
            thr = mb%th
            err(1) = max(err(1), maxval(abs(ma%th([1, 4, 5]) - mb%th([1, 4, 5]))), &
                         abs(ma%q_sway - mb%q_sway))
            err(2) = max(err(2), abs(ma%th(1) - mb%th(1)))
        end do
    end function scene_errors

    ! ---------------------------------------------------------------------------------------
    !> The pose map of elastic_gen against the maximal coordinates, at general states (body
    !! turned, tilted, swinging, cables stretched and stretching): maximal -> generalized ->
    !! maximal gives back R*, the body frame, v* and omega to roundoff; the stretch states
    !! are |C - B| - L0 and |D - A| - L0; and the generalized equations of motion move the
    !! pose as Newton-Euler does: the time derivative of the maximal state along the
    !! generalized flow (central differences of gen_to_maximal) equals the maximal model's
    !! right-hand side (R*', v*', omega'), which checks the jets (J and its derivative).
    subroutine test_coordinates(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el
        type(elastic_gen_t) :: gen
        type(status_t) :: st
        real(dp) :: th(5), thd(5), beta(5), y(ELASTIC_NSTATE), y2(ELASTIC_NSTATE), yg(GEN_NSTATE)
        real(dp) :: fg(GEN_NSTATE), fm(ELASTIC_NSTATE), yp(ELASTIC_NSTATE), ym(ELASTIC_NSTATE)
        real(dp) :: e_pose, e_vel, e_str, e_flow, l0(2), c(3), d(3), h, scale, wb(3), rr(3, 3)
        integer :: trial
        el%p = cylinder(1.8_dp)
        el%p%lambda = 0.6_dp
        el%p%r = 0.8_dp
        el%stiffness = 1.0e4_dp
        el%damping = 0.2_dp
        el%mode = CABLE_TAUT
        e_pose = 0; e_vel = 0; e_str = 0; e_flow = 0
        do trial = 1, 4
            th = [0.1_dp*trial - 0.2_dp, 0.05_dp + 0.1_dp*trial, 0.3_dp + 1.4_dp*trial, &
                  0.4_dp - 0.25_dp*trial, 0.0_dp]
            call solve_theta5(el%p, th, st)
            thd(1:4) = [0.2_dp, -0.1_dp, 0.3_dp, -0.25_dp]*(0.5_dp + 0.2_dp*trial)
            beta = beta_coeffs(el%p, th)
            thd(5) = sum(beta(1:4)*thd(1:4))/beta(5)
            y = elastic_from_angles(el%p, th, thd)
            ! stretch the cables and give them stretching rates
            el%l0 = [el%p%big_l, el%p%big_lp]*(1.0_dp - [2.0e-3_dp, 3.0e-3_dp]*trial)
            y(4:6) = y(4:6) + [0.01_dp, -0.02_dp, 0.015_dp]*trial
            call maximal_to_gen(el, y, yg, st)
            call t%check('coordinates: maximal -> generalized', st%code == 0)
            y2 = gen_to_maximal(el, yg)
            e_pose = max(e_pose, maxval(abs(y2(1:3) - y(1:3))), &
                         maxval(abs(quat_to_matrix(y2(7:10)) - quat_to_matrix(y(7:10)))))
            e_vel = max(e_vel, maxval(abs(y2(4:6) - y(4:6))), maxval(abs(y2(11:13) - y(11:13))))
            rr = quat_to_matrix(y(7:10))
            c = y(1:3) + matmul(rr, [-el%p%r*sin(el%p%lambda), 0.0_dp, el%p%r*cos(el%p%lambda)])
            d = c - rr(:, 3)
            l0 = natural_lengths(el)
            e_str = max(e_str, abs(yg(5) - (norm2(c - [0.0_dp, -el%p%big_b, 0.0_dp]) - l0(1))), &
                        abs(yg(6) - (norm2(d) - l0(2))))
            ! the flow
            gen%el = el
            call gen%rhs(0.0_dp, yg, fg, st)
            call el%rhs(0.0_dp, y, fm, st)
            h = 1.0e-5_dp
            yp = gen_to_maximal(el, yg + h*fg)
            ym = gen_to_maximal(el, yg - h*fg)
            scale = max(1.0_dp, maxval(abs(fm)))
            e_flow = max(e_flow, maxval(abs((yp(1:6) - ym(1:6))/(2*h) - fm(1:6)))/scale)
            wb = (yp(11:13) - ym(11:13))/(2*h)
            e_flow = max(e_flow, maxval(abs(wb - fm(11:13)))/scale)
        end do
        write (*, '(a,4es10.2)') '  pose, velocities, stretches, flow: ', e_pose, e_vel, e_str, &
            e_flow
        call t%check_close('coordinates: pose back to roundoff', e_pose, 0.0_dp, atol=1.0e-13_dp)
        call t%check_close('coordinates: velocities back to roundoff', e_vel, 0.0_dp, &
                           atol=1.0e-12_dp)
        call t%check_close('coordinates: the stretch states are the cables'' stretches', e_str, &
                           0.0_dp, atol=1.0e-14_dp)
        call t%check_close('coordinates: generalized flow = Newton-Euler (central differences)', &
                           e_flow, 0.0_dp, atol=1.0e-8_dp)
    end subroutine test_coordinates

    !> Over stiffness 1e3 ... 1e8 and damping 0.01 ... 0.5 (four corners
    !! and middles: (1e3, 0.01), (1e4, 0.5), (1e6, 0.01), (1e8, 0.1)) at rtol 1e-6, 1e-8,
    !! 1e-10, the largest error in theta1, theta4, theta5 and Q over tau = 0 ... 20 is at most
    !! 30 rtol.  Each reference (Radau 1e-13) is confirmed by LSODA at rtol 1e-13 in the
    !! maximal coordinates to 1e-9 where that takes under 1e5 steps (k <= 1e6).
    subroutine test_follows(t)
        type(tester_t), intent(inout) :: t
        real(dp), parameter :: kk(4) = [1.0e3_dp, 1.0e4_dp, 1.0e6_dp, 1.0e8_dp]
        real(dp), parameter :: zz(4) = [0.01_dp, 0.5_dp, 0.01_dp, 0.1_dp]
        type(elastic_t) :: el
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: y0(ELASTIC_NSTATE), rtol, err(2), agree(2)
        real(dp), allocatable :: yref(:, :), ys(:, :)
        integer :: i, ir
        character(len=60) :: tag
        character(len=100) :: name
        allocate (yref(ELASTIC_NSTATE, 0:NOUT), ys(ELASTIC_NSTATE, 0:NOUT))
        do i = 1, size(kk)
            call issue_scene(kk(i), zz(i), el, y0)
            write (tag, '(a,es7.1,a,f4.2)') 'k = ', kk(i), ', zeta = ', zz(i)
            call solve_scene(el, y0, SOLVER_RADAU, 1.0e-13_dp, yref, st, stat)
            call t%check(trim(tag)//': reference runs', stat%code == 0)
            if (kk(i) <= 1.0e6_dp) then
                call solve_scene(el, y0, SOLVER_LSODA, 1.0e-13_dp, ys, st, stat)
                agree = scene_errors(el, ys, yref)
                write (*, '(a,es10.2)') '  '//trim(tag)//': reference against LSODA 1e-13: ', &
                    agree(1)
                call t%check(trim(tag)//': reference = LSODA 1e-13 to 1e-9', stat%code == 0 &
                             .and. agree(1) < 1.0e-9_dp)
            end if
            do ir = 1, 3
                rtol = 10.0_dp**(-4 - 2*ir)
                call solve_scene(el, y0, SOLVER_RADAU, rtol, ys, st, stat)
                err = scene_errors(el, ys, yref)
                write (*, '(a,es8.1,a,f6.2,a,i6,a)') '  '//trim(tag)//', rtol ', rtol, &
                    ': error ', err(1)/rtol, ' rtol, ', st%steps, ' steps'
                write (name, '(a,es7.1,a)') trim(tag)//', rtol ', rtol, ': error <= 30 rtol'
                call t%check(trim(name), stat%code == 0 .and. err(1) <= 30*rtol)
            end do
        end do
    end subroutine test_follows

    !> Where the generalized chart degenerates (quality below 0.05) Radau goes on in the
    !! maximal coordinates and comes back above 0.1.  The stiff-cable scene does not get there,
    !! so the limits are raised into the range its motion sweeps (at 30 % and 70 % of the
    !! range of the chart's quality at the output times of a reference): the run then changes
    !! coordinates many times, both ways, and its error still follows rtol; so does a run in
    !! the maximal coordinates alone.
    subroutine test_recoords(t)
        type(tester_t), intent(inout) :: t
        real(dp), parameter :: rtol = 1.0e-8_dp
        type(elastic_t) :: el
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: y0(ELASTIC_NSTATE), err(2), q(0:NOUT), lim(2)
        real(dp), allocatable :: yref(:, :), ys(:, :)
        integer :: k, nre, nre_max
        allocate (yref(ELASTIC_NSTATE, 0:NOUT), ys(ELASTIC_NSTATE, 0:NOUT))
        call issue_scene(1.0e4_dp, 0.1_dp, el, y0)
        call solve_scene(el, y0, SOLVER_RADAU, 1.0e-12_dp, yref, st, stat, recoords=nre)
        call t%check('reference in the generalized chart throughout', stat%code == 0 &
                     .and. nre == 0)
        do k = 0, NOUT
            q(k) = chart_quality(el, yref(:, k))
        end do
        lim = minval(q) + [0.3_dp, 0.7_dp]*(maxval(q) - minval(q))
        call solve_scene(el, y0, SOLVER_RADAU, rtol, ys, st, stat, limits=lim, recoords=nre)
        err = scene_errors(el, ys, yref)
        write (*, '(a,2f7.3,a,i0,a,i0,a,f6.2,a)') '  chart limits ', lim, ': ', nre, &
            ' changes of coordinates, ', st%steps, ' steps, error ', err(1)/rtol, ' rtol'
        call t%check('limits inside the motion: >= 6 changes of coordinates', &
                     stat%code == 0 .and. nre >= 6)
        call t%check('limits inside the motion: error <= 30 rtol', stat%code == 0 .and. &
                     err(1) <= 30*rtol)
        call solve_scene(el, y0, SOLVER_RADAU, rtol, ys, st, stat, limits=[2.0_dp, 2.0_dp], &
                         recoords=nre_max)
        err = scene_errors(el, ys, yref)
        write (*, '(a,i0,a,f6.2,a)') '  maximal coordinates alone: ', st%steps, &
            ' steps, error ', err(1)/rtol, ' rtol'
        call t%check('maximal coordinates alone: no change, error <= 30 rtol', &
                     stat%code == 0 .and. nre_max == 0 .and. err(1) <= 30*rtol)
    end subroutine test_recoords

    !> Damping 0.01, at k = 1e6 and 1e8 Radau (rtol 1e-9) reaches a theta1
    !! error below the 2.5e-9 for which CVODE needs 37 791 steps at k = 1e6 (and far below
    !! the 1.3e-7 for which it needs 318 366 at k = 1e8) in under a tenth of CVODE's steps
    !! at k = 1e6; and at k = 1e6 with fewer right-hand sides plus Jacobians than LSODA needs
    !! even for a larger error (rtol 1e-10: 47 000 steps for 1.2e-8; make bench sets LSODA
    !! at rtol 1e-12 against it at both stiffnesses).
    subroutine test_cvode(t)
        type(tester_t), intent(inout) :: t
        real(dp), parameter :: kk(2) = [1.0e6_dp, 1.0e8_dp]
        type(elastic_t) :: el
        type(integrator_stats_t) :: st, sl
        type(status_t) :: stat, stat2
        real(dp) :: y0(ELASTIC_NSTATE), err(2), errl(2)
        real(dp), allocatable :: yref(:, :), ys(:, :)
        integer :: i
        character(len=20) :: tag
        allocate (yref(ELASTIC_NSTATE, 0:NOUT), ys(ELASTIC_NSTATE, 0:NOUT))
        do i = 1, 2
            call issue_scene(kk(i), 0.01_dp, el, y0)
            write (tag, '(a,i0)') 'k = 1e', nint(log10(kk(i)))
            call solve_scene(el, y0, SOLVER_RADAU, 1.0e-13_dp, yref, st, stat)
            call solve_scene(el, y0, SOLVER_RADAU, 1.0e-9_dp, ys, st, stat)
            err = scene_errors(el, ys, yref)
            write (*, '(a,es10.2,a,i0,a,i0,a,i0)') '  '//trim(tag)//': Radau rtol 1e-9: theta1 '// &
                'error ', err(2), ', steps ', st%steps, ', rhs ', st%rhs_evals, ', jac ', &
                st%jac_evals
            call t%check(trim(tag)//': Radau runs', stat%code == 0)
            call t%check(trim(tag)//': theta1 error below CVODE''s 2.5e-9 (and 1.3e-7)', &
                         err(2) < min(CVODE_ERR_1E6, CVODE_ERR_1E8))
            call t%check(trim(tag)//': under 1/10 of CVODE''s steps at k = 1e6 (and 1e8)', &
                         10*st%steps <= min(CVODE_STEPS_1E6, CVODE_STEPS_1E8))
            if (i == 1) then
                call solve_scene(el, y0, SOLVER_LSODA, 1.0e-10_dp, ys, sl, stat2)
                errl = scene_errors(el, ys, yref)
                write (*, '(a,es10.2,a,i0,a,i0,a,i0)') '  '//trim(tag)//': LSODA rtol 1e-10: '// &
                    'theta1 error ', errl(2), ', steps ', sl%steps, ', rhs ', sl%rhs_evals, &
                    ', jac ', sl%jac_evals
                call t%check(trim(tag)//': fewer rhs + Jacobians than LSODA with a larger error', &
                             stat2%code == 0 .and. errl(2) > err(2) .and. &
                             st%rhs_evals + st%jac_evals < sl%rhs_evals + sl%jac_evals)
            end if
        end do
    end subroutine test_cvode

    !> At rtol 1e-12 (damping 0.01) Radau's steps at k = 1e8 are at most
    !! 3 times those at k = 1e6; input/cylinder_l180_elastic.nml (k = 1e6, damping 0.05,
    !! tau = 0 ... 60, rtol 1e-10) takes at most a fifth of the 58 469 steps it took before.
    subroutine test_blowup(t)
        type(tester_t), intent(inout) :: t
        type(elastic_t) :: el
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        type(deck_t) :: d
        type(run_summary_t) :: sm
        real(dp) :: y0(ELASTIC_NSTATE)
        real(dp), allocatable :: ys(:, :)
        integer :: steps(2), i
        logical :: ok
        allocate (ys(ELASTIC_NSTATE, 0:NOUT))
        ok = .true.
        do i = 1, 2
            call issue_scene(10.0_dp**(4 + 2*i), 0.01_dp, el, y0)
            call solve_scene(el, y0, SOLVER_RADAU, 1.0e-12_dp, ys, st, stat)
            ok = ok .and. stat%code == 0
            steps(i) = st%steps
        end do
        write (*, '(a,2i7)') '  rtol 1e-12, steps at k = 1e6, 1e8: ', steps
        call t%check('rtol 1e-12: runs finish', ok)
        call t%check('rtol 1e-12: steps at k = 1e8 <= 3 x steps at k = 1e6', &
                     steps(2) <= 3*steps(1))
        call read_deck('input/cylinder_l180_elastic.nml', d, stat)
        call scratch_dir('build/test_elastic_radau')
        if (stat%code == 0) call run_simulation(d, 'build/test_elastic_radau', sm, stat)
        write (*, '(a,i0,a,a)') '  cylinder_l180_elastic: ', sm%steps, ' steps, method ', &
            trim(sm%method)
        call t%check('cylinder_l180_elastic runs (Radau)', stat%code == 0 .and. &
                     trim(sm%method) == 'radau')
        call t%check('cylinder_l180_elastic: <= 1/5 of the 58 469 steps before', &
                     5*sm%steps <= STEPS_BEFORE)
    end subroutine test_blowup

    !> &integration method: 'auto' takes Radau for the elastic model and LSODA for the
    !! paper's, 'lsoda' and 'radau' take that integrator for either model (the summary's
    !! method key says which ran; the paper's model by Radau conserves energy to 10 rtol);
    !! an unknown word is a deck error naming the group, the variable and the words allowed.
    subroutine test_method_word(t)
        type(tester_t), intent(inout) :: t
        character(len=*), parameter :: dir = 'build/test_elastic_radau'
        character(len=5), parameter :: words(3) = ['auto ', 'lsoda', 'radau']
        character(len=7), parameter :: models(2) = ['kane   ', 'elastic']
        character(len=5) :: expect
        type(deck_t) :: d
        type(status_t) :: stat
        type(run_summary_t) :: sm
        integer :: iw, im
        call scratch_dir(dir)
        do im = 1, 2
            do iw = 1, 3
                call write_deck(dir//'/method.nml', trim(models(im)), trim(words(iw)))
                call read_deck(dir//'/method.nml', d, stat)
                if (stat%code == 0) call run_simulation(d, dir, sm, stat)
                expect = words(iw)
                if (iw == 1) expect = merge('radau', 'lsoda', im == 2)
                call t%check('method = '''//trim(words(iw))//''', model = '''// &
                             trim(models(im))//''': runs '//trim(expect), stat%code == 0 .and. &
                             trim(sm%method) == trim(expect))
                if (im == 1 .and. iw == 3) call t%check('paper''s model by Radau: energy '// &
                    'within 10 rtol', sm%max_abs_energy_error <= 10*1.0e-9_dp)
            end do
        end do
        call write_deck(dir//'/method.nml', 'elastic', 'rk4')
        call read_deck(dir//'/method.nml', d, stat)
        call t%check('method = ''rk4'': deck error', stat%code == ERR_DECK)
        if (stat%code /= 0) call t%check('method = ''rk4'': the message names the variable '// &
            'and the words allowed', index(stat%msg, '&integration method = ''rk4''') > 0 .and. &
            index(stat%msg, 'auto, lsoda, radau') > 0)
    contains
        subroutine write_deck(path, model, word)
            character(len=*), intent(in) :: path, model, word
            character, parameter :: NL = new_line('a')
            call write_text(path, '&scene title = ''method'', model = '''//model//''' /'//NL// &
                '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 1.8 /'//NL// &
                '&body mass = 1.0 /'//NL// &
                '&integration tau_end = 2.0, dtau_out = 0.1, rtol = 1e-9, '// &
                'atol = 1e-11, method = '''//word//''' /'//NL)
        end subroutine write_deck
    end subroutine test_method_word

end module test_elastic_radau
