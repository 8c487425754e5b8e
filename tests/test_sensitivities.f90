!> Tests of the forward sensitivities: the integrators' staggered direct method
!! against an exact solution, the model's df/dp along every parameter against differences
!! of its accelerations, the record model's derivatives against differences of whole
!! runs (every fit parameter and some budget inputs, symmetric and asymmetric rig, small and
!! large amplitude, LSODA and Radau), a record fit and its budget by sensitivities against
!! the same by differences of runs, the monodromy as the orbit's sensitivities against
!! the variational equations integrated with the orbit, and simulate's global error within
!! 10 rtol.
module test_sensitivities
    use kinds, only: dp, deg
    use status, only: status_t
    use testing, only: tester_t, msg_of_ => msg_of, write_text, run_cmd => run, fresh_dir, &
        count_lines, file_has, empty_dir
    use ode_system, only: ode_system_t, integrator_t, integrator_stats_t, default_sens_point
    use integrators, only: new_integrator, SOLVER_LSODA, SOLVER_RADAU, SENS_FORWARD, &
                           SENS_DIFFERENCES
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, start_of, accuracy_of, read_record
    use rig, only: rig_t, start_t, accuracy_t, make_pendulum
    use inputs, only: set_input, input_value
    use record_fit, only: record_model, record_model_sens, record_fit_t, fit_problem, &
        fresh_jacobian
    use records, only: record_t
    use identify, only: identify_result_t, identify_record
    use geometry, only: pendulum_t
    use floquet, only: floquet_result_t, floquet_analysis
    use rig, only: start_state
    use bifilar_model, only: NSTATE, bifilar_t, sens_dir_t, chart_accelerations
    use kane_run, only: kane_run_t, kane_run_start
    use run_loop, only: drive
    use keep_sink, only: keep_t
    use work_precision, only: trajectory_errors
    use estimator, only: gauss_newton_gain
    use unused_arg, only: unused
    implicit none
    private

    public :: run_sensitivities_tests

    !> A harmonic oscillator y1' = y2, y2' = -k y1 and a stiff component
    !! y3' = -lam (y3 - cos t): sensitivities to k and lam with exact solutions.
    type, extends(ode_system_t) :: osc_t
        real(dp) :: k = 4.0_dp, lam = 1.0e4_dp
    contains
        procedure :: rhs => osc_rhs
        procedure :: jacobian => osc_jacobian
        procedure :: has_jacobian => osc_has_jacobian
        procedure :: sens_point => osc_sens_point
    end type osc_t

contains

    subroutine run_sensitivities_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        if (t%want('sensitivities: integrators against an exact solution')) call test_exact(t)
        if (t%want('sensitivities: df/dp of each parameter against differences of the rhs')) &
            call test_dfdp(t)
        if (t%want('sensitivities: the record model against differences of whole runs')) &
            call test_record_model(t)
        if (t%want('sensitivities: a record fit and its budget, forward = differences')) &
            call test_fit(t)
        if (t%want('sensitivities: the record fit takes its Jacobian again on short steps')) &
            call test_jacobian_reuse(t)
        if (t%want('sensitivities: monodromy, forward = variational system')) &
            call test_monodromy(t)
        if (t%want('sensitivities: global error within 10 rtol')) call test_global_error(t)
        if (t%want('sensitivities: a bad &integration sensitivities is one line, no file')) &
            call test_bad_word(t, exe)
    end subroutine run_sensitivities_tests

    !> &integration sensitivities = 'exact' through the executable: exit 2, one line on
    !! stderr naming the deck, the variable and the words allowed, nothing on stdout, no
    !! file in --out.
    subroutine test_bad_word(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: d = 'build/test_sensitivities/bad'
        character, parameter :: NL = new_line('a')
        integer :: ex
        call fresh_dir(d)
        call write_text(d//'/bad.nml', '&scene title = ''bad word'', analyses = ''floquet'' /'// &
            NL//'&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 2.0 /'//NL// &
            '&body mass = 1.0 /'//NL//'&integration sensitivities = ''exact'' /'//NL)
        ex = run_cmd(exe//' '//d//'/bad.nml --out '//d//'/out', d)
        call t%check('sensitivities: a bad word: exit 2, one stderr line naming the deck, '// &
            'the variable and the words allowed, no output', all([ex == 2, &
            count_lines(d//'/stderr') == 1, count_lines(d//'/stdout') == 0, &
            file_has(d//'/stderr', 'bad.nml: &integration sensitivities = ''exact'''), &
            file_has(d//'/stderr', 'allowed: forward, differences'), empty_dir(d//'/out')]))
    end subroutine test_bad_word

    ! ---- the oscillator

    subroutine osc_rhs(sys, t, y, ydot, stat)
        class(osc_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        stat%code = 0
        ydot = [y(2), -sys%k*y(1), -sys%lam*(y(3) - cos(t))]
    end subroutine osc_rhs

    subroutine osc_jacobian(sys, t, y, dfdy, stat)
        class(osc_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        call unused(t)
        call unused(y)
        stat%code = 0
        dfdy = 0.0_dp
        dfdy(1, 2) = 1.0_dp
        dfdy(2, 1) = -sys%k
        dfdy(3, 3) = -sys%lam
    end subroutine osc_jacobian

    logical function osc_has_jacobian(sys)
        class(osc_t), intent(in) :: sys
        osc_has_jacobian = sys%k > 0.0_dp
    end function osc_has_jacobian

    !> df/dk and df/dlam, the Jacobian from ode_system's default.
    subroutine osc_sens_point(sys, t, y, dfdp, stat)
        class(osc_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: dfdp(:, :)
        type(status_t), intent(out) :: stat
        call default_sens_point(sys, t, y, dfdp, stat)
        if (stat%code /= 0) return
        dfdp(:, 1) = [0.0_dp, -y(1), 0.0_dp]
        dfdp(:, 2) = [0.0_dp, 0.0_dp, -(y(3) - cos(t))]
    end subroutine osc_sens_point

    !> Both integrators (LSODA through its non-stiff and stiff phases), the sensitivities in
    !! and out of the error control, against the exact dy/dk and dy/dlam at t = 10, and the
    !! dense output inside the last step against the exact ones there.
    subroutine test_exact(t)
        type(tester_t), intent(inout) :: t
        type(osc_t) :: sys
        class(integrator_t), allocatable :: s
        type(status_t) :: st
        type(integrator_stats_t) :: stt
        real(dp) :: y(3), s0(3, 2), sv(3, 2), ex(3, 2), a, ap, bp, w, tend, tm, err
        integer :: im, ie
        character(len=40) :: label
        w = sqrt(sys%k)
        a = sys%lam**2/(sys%lam**2 + 1.0_dp)
        ap = 2.0_dp*sys%lam/(sys%lam**2 + 1.0_dp)**2
        bp = (1.0_dp - sys%lam**2)/(sys%lam**2 + 1.0_dp)**2
        tend = 10.0_dp
        do im = 1, 2
            do ie = 0, 1
                write (label, '(a,a,l1)') trim(merge('lsoda', 'radau', im == 1)), &
                    ' error_control=', ie == 1
                call new_integrator(merge(SOLVER_LSODA, SOLVER_RADAU, im == 1), s)
                y = [1.0_dp, 0.0_dp, a]
                call s%init(sys, 0.0_dp, y, 1.0e-10_dp, [1.0e-12_dp], st)
                call t%check('sensitivities: init '//trim(label)//msg_of(st), st%code == 0)
                s0 = 0.0_dp
                s0(3, 2) = ap
                call s%sens_init(sys, s0, st, error_control=ie == 1)
                call t%check('sensitivities: sens_init '//trim(label)//msg_of(st), st%code == 0)
                call s%integrate(sys, tend, y, st)
                call t%check('sensitivities: integrate '//trim(label)//msg_of(st), st%code == 0)
                if (st%code /= 0) cycle
                call s%sens_dense(tend, 0, sv, st)
                ex = exact(tend)
                err = maxval(abs(sv - ex))/maxval(abs(ex))
                call t%check_close('sensitivities: exact at t = 10, '//trim(label), &
                                   1.0_dp + err, 1.0_dp, 1.0e-6_dp)
                ! inside the last step
                stt = s%stats()
                tm = stt%t_current - 0.5_dp*stt%h_last
                call s%sens_dense(tm, 0, sv, st)
                call t%check('sensitivities: dense output inside the step, '//trim(label)// &
                             msg_of(st), st%code == 0)
                ex = exact(tm)
                err = maxval(abs(sv - ex))/maxval(abs(ex))
                call t%check_close('sensitivities: dense output, '//trim(label), &
                                   1.0_dp + err, 1.0_dp, 1.0e-5_dp)
                ! the projections g . s_k (sens_dense_dot: LSODA's own, Radau's by default)
                block
                    real(dp) :: g(3), v(2), v2(2)
                    g = [0.7_dp, 0.0_dp, -1.3_dp]
                    call s%sens_dense_dot(tm, g, v, st)
                    v2 = matmul(g, sv)
                    call t%check_close('sensitivities: g . s_k inside the step = g . the '// &
                                       'dense output, '//trim(label), 1.0_dp + &
                                       maxval(abs(v - v2))/maxval(abs(v2)), 1.0_dp, 1.0e-14_dp)
                    call s%sens_dense_dot(stt%t_current + 2.0_dp*abs(stt%h_last), g, v, st)
                    call t%check('sensitivities: g . s_k beyond the step refused, '// &
                                 trim(label), st%code /= 0)
                end block
                ! out of place: a wrong shape is refused
                block
                    real(dp) :: bad(3, 3)
                    call s%sens_dense(tend, 0, bad, st)
                    call t%check('sensitivities: a wrong shape refused, '//trim(label), &
                                 st%code /= 0)
                end block
            end do
        end do
    contains
        function exact(tt) result(e)
            real(dp), intent(in) :: tt
            real(dp) :: e(3, 2)
            e = 0.0_dp
            e(1, 1) = -tt*sin(w*tt)/(2.0_dp*w)
            e(2, 1) = -(sin(w*tt) + w*tt*cos(w*tt))/(2.0_dp*w)
            e(3, 2) = ap*cos(tt) + bp*sin(tt) - ap*exp(-sys%lam*tt)
        end function exact
    end subroutine test_exact

    !> record_model_sens's derivatives of the model at the samples against central
    !! differences of record_model, for the fit's parameters (I1, c_v, c_q, amplitude, t0)
    !! and inputs of the budget (l, b_prime, mass, b, and lambda, r on the identify_record
    !! rig (unequal cables, offset mass centre), l_prime, g on a symmetric one, where lambda
    !! and r move nothing to first order), 5 and 60 degrees, LSODA and Radau, the angle on
    !! the symmetric rig and the rate on the other.
    subroutine test_record_model(t)
        type(tester_t), intent(inout) :: t
        character(len=16) :: names(11) = [character(len=16) :: 'I1', 'c_v', 'c_q', &
            'amplitude', 't0', 'l', 'b_prime', 'mass', 'lambda', 'b', 'r']
        integer, parameter :: NT = 61
        type(deck_t) :: d
        type(status_t) :: st
        type(rig_t) :: rg, r2
        type(start_t) :: s1, s2
        type(accuracy_t) :: acc
        real(dp) :: ts(NT), xs(size(names)), vals(NT), dv(NT, size(names)), vp(NT), vm(NT)
        real(dp) :: t0, h, fd(NT), err, worst
        integer :: isym, iamp, im, c, i
        logical :: rate
        character(len=60) :: label
        call read_deck('input/identify_record.nml', d, st)
        call t%check('sensitivities: the deck'//msg_of(st), st%code == 0)
        if (st%code /= 0) return
        do i = 1, NT
            ts(i) = 0.05_dp*(i - 1)
        end do
        t0 = 0.3123_dp
        do isym = 1, 2
            do iamp = 1, 2
                do im = 1, 2
                    rg = rig_of(d)
                    rg%c_v = 2.0e-4_dp
                    rg%c_q = 5.0e-4_dp
                    if (isym == 1) then
                        rg%l_prime = rg%l
                        rg%lambda = atan(0.75_dp)
                    end if
                    rate = isym == 2
                    ! lambda moves nothing to first order on the symmetric rig: l' there
                    names(9) = merge('l_prime', 'lambda ', isym == 1)
                    ! nor r (the mass centre off the bisector): g (the time scale) there
                    names(11) = merge('g', 'r', isym == 1)
                    s1 = start_of(d)
                    s1%amplitude = merge(5.0_dp, 60.0_dp, iamp == 1)
                    acc = accuracy_of(d)
                    acc%rtol = 1.0e-10_dp
                    acc%method = merge(SOLVER_LSODA, SOLVER_RADAU, im == 1)
                    write (label, '(a,a,i0,a,a)') trim(merge('symmetric ', 'asymmetric', &
                        isym == 1)), ', ', nint(s1%amplitude), ' deg, ', &
                        trim(merge('lsoda', 'radau', im == 1))
                    do c = 1, size(names)
                        xs(c) = abs(value_of(rg, s1, t0, names(c)))
                    end do
                    call record_model_sens(rg, s1, acc, ts, t0, rate, names, xs, vals, dv, st)
                    call t%check('sensitivities: run, '//trim(label)//msg_of(st), st%code == 0)
                    if (st%code /= 0) cycle
                    worst = 0.0_dp
                    do c = 1, size(names)
                        ! central differences with steps 2h and h, extrapolated (error h^4)
                        ! (the damping, nearly linear and of little effect, by larger steps)
                        h = merge(0.1_dp, 2.0e-3_dp, names(c)(1:2) == 'c_')*xs(c)
                        call moved(names(c), h, r2, s2, t0, vp)
                        if (st%code == 0) call moved(names(c), -h, r2, s2, t0, vm)
                        if (st%code /= 0) exit
                        fd = -(vp - vm)/(2.0_dp*h)/3.0_dp
                        h = 0.5_dp*h
                        call moved(names(c), h, r2, s2, t0, vp)
                        if (st%code == 0) call moved(names(c), -h, r2, s2, t0, vm)
                        if (st%code /= 0) exit
                        fd = fd + 4.0_dp*(vp - vm)/(2.0_dp*h)/3.0_dp
                        err = maxval(abs(dv(:, c) - fd))/max(maxval(abs(fd)), tiny(1.0_dp))
                        call t%check_close('sensitivities: d model/d '//trim(names(c))//', '// &
                                           trim(label), 1.0_dp + err, 1.0_dp, 1.0e-5_dp)
                        ! the column is not trivially small
                        call t%check('sensitivities: d model/d '//trim(names(c))// &
                                     ' not zero, '//trim(label), maxval(abs(fd)) > 0.0_dp)
                        worst = max(worst, err)
                        if (err > 1.0e-5_dp) write (*, '(a,a,a,3es12.4)') 'debug ', names(c), label, &
                            maxval(abs(fd)), maxval(abs(dv(:, c))), err
                    end do
                    call t%check('sensitivities: the differences ran, '//trim(label)// &
                                 msg_of(st), st%code == 0)
                end do
            end do
        end do
    contains
        real(dp) function value_of(r, s, tr, name) result(v)
            type(rig_t), intent(in) :: r
            type(start_t), intent(in) :: s
            real(dp), intent(in) :: tr
            character(len=*), intent(in) :: name
            select case (trim(name))
            case ('I1')
                v = r%inertia(1)
            case ('c_v')
                v = r%c_v
            case ('c_q')
                v = r%c_q
            case ('t0')
                v = tr
            case default
                v = input_value(r, s, name)
            end select
        end function value_of
        !> The model with quantity `name` moved by dx.
        subroutine moved(name, dx, r, s, tr, v)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: dx
            type(rig_t), intent(out) :: r
            type(start_t), intent(out) :: s
            real(dp), intent(in) :: tr
            real(dp), intent(out) :: v(:)
            real(dp) :: tt
            r = rg
            s = s1
            tt = tr
            select case (trim(name))
            case ('I1')
                r%inertia(1) = r%inertia(1) + dx
            case ('c_v')
                r%c_v = r%c_v + dx
            case ('c_q')
                r%c_q = r%c_q + dx
            case ('t0')
                tt = tr + dx
            case default
                call set_input(r, s, name, input_value(rg, s1, name) + dx)
            end select
            call record_model(r, s, acc, ts, tt, rate, v, st)
        end subroutine moved
    end subroutine test_record_model

    !> The first 10 s of input/identify_record_swing.dat fitted (I1, c_v, c_q) with its
    !! first-order budget, by forward sensitivities (rtol 1e-10) and by differences of whole
    !! runs (rtol 1e-12): I1 and its u agree to 1e-6, every row of the budget to 2e-6 of
    !! u(I1) beyond the differences' own scatter, and the forward fit evaluates the model
    !! fewer times.  The same with the sensitivities in the error control (&integration
    !! sensitivity_error_control).  The differences' scatter is measured: a second fit by
    !! differences at rtol 3e-13 (the steps of the runs move, and a row whose input the fit
    !! largely absorbs, the release amplitude, loses digits to the cancellation: its
    !! differences scatter by about 3e-4 of the row).
    subroutine test_fit(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(record_t) :: part
        type(status_t) :: st
        type(identify_result_t) :: rf, rd, rc, rd2
        real(dp) :: scatter
        integer :: i
        logical :: ok
        call first_ten_seconds(t, 'fit', d, part, ok)
        if (.not. ok) return
        d%measurement%monte_carlo = 0
        d%integration%sensitivities = 'forward'
        call identify_record(d, part, rf, st)
        call t%check('sensitivities: fit forward'//msg_of(st), st%code == 0)
        if (st%code /= 0) return
        d%integration%sensitivity_error_control = .true.
        call identify_record(d, part, rc, st)
        call t%check('sensitivities: fit forward in the error control'//msg_of(st), st%code == 0)
        if (st%code /= 0) return
        d%integration%sensitivity_error_control = .false.
        d%integration%sensitivities = 'differences'
        d%integration%rtol = 1.0e-12_dp
        d%integration%atol = 1.0e-14_dp
        call identify_record(d, part, rd, st)
        call t%check('sensitivities: fit differences'//msg_of(st), st%code == 0)
        if (st%code /= 0) return
        d%integration%rtol = 3.0e-13_dp
        d%integration%atol = 3.0e-15_dp
        call identify_record(d, part, rd2, st)
        call t%check('sensitivities: fit differences, rtol 3e-13'//msg_of(st), st%code == 0 &
                     .and. size(rd2%budget) == size(rd%budget))
        if (st%code /= 0 .or. size(rd2%budget) /= size(rd%budget)) return
        call t%check_close('sensitivities: fit I1, forward = differences', rf%i1, rd%i1, &
                           1.0e-6_dp)
        call t%check_close('sensitivities: fit u(I1), forward = differences', rf%u_i1, &
                           rd%u_i1, 1.0e-6_dp)
        call t%check_close('sensitivities: fit I1, in the error control = differences', &
                           rc%i1, rd%i1, 1.0e-6_dp)
        call t%check_close('sensitivities: fit u(I1), in the error control = differences', &
                           rc%u_i1, rd%u_i1, 1.0e-6_dp)
        call t%check('sensitivities: fit, budgets of the same rows', &
                     size(rf%budget) == size(rd%budget) .and. size(rf%budget) > 3 .and. &
                     size(rc%budget) == size(rd%budget))
        if (size(rf%budget) /= size(rd%budget)) return
        do i = 1, size(rf%budget)
            ! each row's contribution to u(I1), to 2e-6 of u(I1) beyond twice the scatter of
            ! the reference's own differences
            scatter = abs(rd%budget(i)%contribution - rd2%budget(i)%contribution)
            call t%check_close('sensitivities: fit budget '//trim(rd%budget(i)%input)// &
                               ', forward = differences', rf%budget(i)%contribution, &
                               rd%budget(i)%contribution, 0.0_dp, &
                               2.0e-6_dp*rd%u_i1 + 2.0_dp*scatter)
            call t%check('sensitivities: fit budget '//trim(rd%budget(i)%input)//' the same row', &
                         rf%budget(i)%input == rd%budget(i)%input)
            if (size(rc%budget) == size(rd%budget)) &
                call t%check_close('sensitivities: fit budget '//trim(rd%budget(i)%input)// &
                                   ', in the error control = differences', &
                                   rc%budget(i)%contribution, rd%budget(i)%contribution, &
                                   0.0_dp, 2.0e-6_dp*rd%u_i1 + 2.0_dp*scatter)
        end do
        call t%check('sensitivities: the forward fit evaluates the model fewer times', &
                     rf%evaluations < rd%evaluations)
    end subroutine test_fit

    !> The paper's parallelepipeds (box_stable, box_unstable), the cylinder and the tall box
    !! (modulus 2.65e3) at 45 deg: the multipliers from the orbit's forward sensitivities
    !! (six columns of the half-period map) against those from the variational equations
    !! integrated with the orbit (the whole map), within 1e-8, with each integrator.
    subroutine test_monodromy(t)
        type(tester_t), intent(inout) :: t
        character(len=*), parameter :: decks(4) = [character(len=20) :: 'box_stable', &
            'box_unstable', 'cylinder_torsion', 'box_tall_floquet']
        type(deck_t) :: d
        type(status_t) :: st, st2
        type(pendulum_t) :: p
        type(floquet_result_t) :: rf, rd
        integer :: k, im
        real(dp) :: err
        character(len=60) :: label
        do k = 1, size(decks)
            call read_deck('input/'//trim(decks(k))//'.nml', d, st)
            if (st%code == 0) call make_pendulum(rig_of(d), p, st)
            call t%check('sensitivities: monodromy deck '//trim(decks(k))//msg_of(st), &
                         st%code == 0)
            if (st%code /= 0) cycle
            p%stab_rate = 0.0_dp
            do im = 1, 2
                label = trim(decks(k))//', '//trim(merge('lsoda', 'radau', im == 1))
                call floquet_analysis(p, 45*deg, 1.0e-10_dp, 1, rf, st, &
                                      merge(SOLVER_LSODA, SOLVER_RADAU, im == 1), SENS_FORWARD)
                call floquet_analysis(p, 45*deg, 1.0e-10_dp, 1, rd, st2, &
                                      merge(SOLVER_LSODA, SOLVER_RADAU, im == 1), &
                                      SENS_DIFFERENCES)
                call t%check('sensitivities: monodromy runs, '//trim(label)//msg_of(st)// &
                             msg_of(st2), st%code == 0 .and. st2%code == 0)
                if (st%code /= 0 .or. st2%code /= 0) cycle
                err = set_distance(rf%multipliers, rd%multipliers)
                call t%check_close('sensitivities: multipliers, forward = variational, '// &
                                   trim(label), 1.0_dp + err, 1.0_dp, 1.0e-8_dp)
                call t%check_close('sensitivities: largest modulus, '//trim(label), &
                                   rf%max_modulus, rd%max_modulus, 1.0e-8_dp)
            end do
        end do
    end subroutine test_monodromy

    !> simulate's run (kane_run with global = .true.) of the cylinder (input/cylinder_l180.nml)
    !! and of it with b = 1.3 b' released from 80 degrees, at rtol 1e-7 and 1e-10, against
    !! a run at rtol/1000: the largest angle error over the rows within 10 rtol (the whole
    !! range and the other scenes: bench_global_error in make bench).
    subroutine test_global_error(t)
        type(tester_t), intent(inout) :: t
        real(dp), parameter :: rtols(2) = [1.0e-7_dp, 1.0e-10_dp]
        type(deck_t) :: d
        type(status_t) :: st
        type(rig_t) :: rg
        type(start_t) :: s0
        type(pendulum_t) :: p
        real(dp) :: y0(NSTATE), th0(5), eth, eq, ee
        real(dp), allocatable :: times(:), ys(:, :), yref(:, :)
        integer :: k, j, n, i
        character(len=60) :: label
        call read_deck('input/cylinder_l180.nml', d, st)
        call t%check('sensitivities: global error deck'//msg_of(st), st%code == 0)
        if (st%code /= 0) return
        n = nint(d%integration%tau_end/d%integration%dtau_out)
        allocate (times(0:n), ys(NSTATE, 0:n), yref(NSTATE, 0:n))
        do i = 0, n
            times(i) = d%integration%dtau_out*i
        end do
        do k = 1, 2
            rg = rig_of(d)
            s0 = start_of(d)
            if (k == 2) then
                rg%b = 1.3_dp*rg%b_prime
                s0%amplitude = 80.0_dp
            end if
            call make_pendulum(rg, p, st)
            if (st%code == 0) call start_state(s0, p, y0, th0, st)
            call t%check('sensitivities: global error scene'//msg_of(st), st%code == 0)
            if (st%code /= 0) cycle
            do j = 1, size(rtols)
                write (label, '(a,a,es8.1)') trim(merge('cylinder_l180         ', &
                    'b = 1.3 b'', 80 degrees', k == 1)), ', rtol ', rtols(j)
                call run(rtols(j)/1000, rtols(j)/1.0e5_dp, .false., yref)
                if (st%code == 0) call run(rtols(j), rtols(j)/100, .true., ys)
                call t%check('sensitivities: global error runs, '//trim(label)//msg_of(st), &
                             st%code == 0)
                if (st%code /= 0) cycle
                call trajectory_errors(p, ys, yref, eth, eq, ee)
                call t%check('sensitivities: global error within 10 rtol, '//trim(label), &
                             eth <= 10.0_dp*rtols(j) .and. eth > 0.0_dp)
            end do
        end do
    contains
        subroutine run(rt, at, global, yout)
            real(dp), intent(in) :: rt, at
            logical, intent(in) :: global
            real(dp), intent(out) :: yout(:, 0:)
            type(kane_run_t) :: m
            type(keep_t) :: sink
            yout = 0.0_dp
            call kane_run_start(m, p, y0, th0(3), rt, at, SOLVER_LSODA, times(n), 'test', st, &
                                global=global)
            if (st%code /= 0) return
            allocate (sink%ys(NSTATE, 0:n))
            call drive(m, times, sink, st)
            if (st%code == 0) yout = sink%ys
        end subroutine run
    end subroutine test_global_error

    !> The model's df/dp (bifilar_t's sens_point) along each of its scaled parameters alone
    !! (L, L', B, r, lambda, the three moments, c_v, c_q) and along a direction that moves
    !! them all, at a moving, tilted state of an asymmetric rig with damping and Baumgarte's
    !! term, against the central differences of the accelerations (chart_accelerations)
    !! extrapolated from steps h and h/2 (Richardson): within 1e-8 of the largest
    !! acceleration's change (the differences' own error is about 1e-11).
    subroutine test_dfdp(t)
        type(tester_t), intent(inout) :: t
        character(len=*), parameter :: names(11) = [character(len=8) :: 'L', "L'", 'B', &
            'r', 'lambda', 'I1', 'I2', 'I3', 'c_v', 'c_q', 'all']
        type(bifilar_t) :: sys
        type(pendulum_t) :: p
        type(sens_dir_t) :: dirs(11)
        type(status_t) :: st
        real(dp) :: y(NSTATE), dfdp(NSTATE, 11), fd(5), fd2(5), err
        integer :: j
        p%big_l = 3.1_dp
        p%big_lp = 2.9_dp
        p%big_b = 1.2_dp
        p%r = 0.55_dp
        p%lambda = 0.7_dp
        p%inertia = [0.31_dp, 0.42_dp, 0.19_dp]
        p%c_v = 0.02_dp
        p%c_q = 0.03_dp
        p%stab_rate = 1.0_dp
        p%btilde = reshape([0.8_dp, 0.6_dp, 0.0_dp, -0.6_dp, 0.8_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                            1.0_dp], [3, 3])
        y = [0.05_dp, 0.12_dp, -0.07_dp, 0.4_dp, 0.03_dp, 0.02_dp, -0.05_dp, 0.08_dp, -0.6_dp, &
             0.04_dp]
        dirs(1)%big_l = 1.0_dp
        dirs(2)%big_lp = 1.0_dp
        dirs(3)%big_b = 1.0_dp
        dirs(4)%r = 1.0_dp
        dirs(5)%lambda = 1.0_dp
        dirs(6)%inertia(1) = 1.0_dp
        dirs(7)%inertia(2) = 1.0_dp
        dirs(8)%inertia(3) = 1.0_dp
        dirs(9)%c_v = 1.0_dp
        dirs(10)%c_q = 1.0_dp
        dirs(11) = sens_dir_t([0.3_dp, -0.2_dp, 0.1_dp], 0.5_dp, -0.4_dp, 0.7_dp, -0.6_dp, &
                              0.9_dp, 0.35_dp, -0.25_dp)
        sys%p = p
        sys%dirs = dirs
        call sys%sens_point(0.0_dp, y, dfdp, st)
        call t%check('sensitivities: df/dp at the state'//msg_of(st), st%code == 0)
        if (st%code /= 0) return
        do j = 1, size(dirs)
            call central(dirs(j), 1.0e-4_dp, fd)
            call central(dirs(j), 0.5e-4_dp, fd2)
            fd = (4.0_dp*fd2 - fd)/3.0_dp
            err = maxval(abs(dfdp(6:10, j) - fd))/max(maxval(abs(fd)), 1.0e-12_dp)
            call t%check_close('sensitivities: df/dp along '//trim(names(j))// &
                               ' = differences of the accelerations', 1.0_dp + err, 1.0_dp, &
                               1.0e-8_dp)
            call t%check('sensitivities: df/dp along '//trim(names(j))//' is not 0', &
                         maxval(abs(fd)) > 1.0e-6_dp)
            call t%check('sensitivities: df/dp along '//trim(names(j))//' leaves the rates', &
                         all(dfdp(1:5, j) == 0.0_dp))
        end do
    contains
        !> Central differences of the accelerations along direction dd with step h.
        subroutine central(dd, h, g)
            type(sens_dir_t), intent(in) :: dd
            real(dp), intent(in) :: h
            real(dp), intent(out) :: g(5)
            real(dp) :: ap(5), am(5)
            type(status_t) :: s1, s2
            call chart_accelerations(moved(dd, h), y, ap, s1)
            call chart_accelerations(moved(dd, -h), y, am, s2)
            g = (ap - am)/(2.0_dp*h)
            if (s1%code /= 0 .or. s2%code /= 0) g = huge(1.0_dp)
        end subroutine central
        !> The pendulum moved by h along dd.
        function moved(dd, h) result(q)
            type(sens_dir_t), intent(in) :: dd
            real(dp), intent(in) :: h
            type(pendulum_t) :: q
            q = p
            q%big_l = p%big_l + h*dd%big_l
            q%big_lp = p%big_lp + h*dd%big_lp
            q%big_b = p%big_b + h*dd%big_b
            q%r = p%r + h*dd%r
            q%lambda = p%lambda + h*dd%lambda
            q%inertia = p%inertia + h*dd%inertia
            q%c_v = p%c_v + h*dd%c_v
            q%c_q = p%c_q + h*dd%c_q
        end function moved
    end subroutine test_dfdp

    !> The record fit's Jacobian taken again: on the whole record (the first 10 s of
    !! input/identify_record_swing.dat), an evaluation a short step from the last (no budget
    !! carried) returns that point's Jacobian (jac_fresh false) with its own, new residuals;
    !! fresh_jacobian then gives the Jacobian computed at the new point (jac_fresh true),
    !! the one a problem that never saw the first point computes there, with the same
    !! residuals.
    subroutine test_jacobian_reuse(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(record_t) :: part
        type(status_t) :: st
        type(record_fit_t) :: prob, other
        real(dp), allocatable :: p0(:), h(:), p(:), r1(:), r2(:), r3(:), r4(:)
        real(dp), allocatable :: j1(:, :), j2(:, :), j3(:, :), j4(:, :)
        integer :: m
        logical :: ok
        call first_ten_seconds(t, 'reuse', d, part, ok)
        if (.not. ok) return
        call fit_problem(rig_of(d), start_of(d), accuracy_of(d), d%measurement, part, prob, p0, h)
        prob%nuse = size(part%t)
        other = prob
        m = prob%nres()
        allocate (r1(m), r2(m), r3(m), r4(m), j1(m, 3), j2(m, 3), j3(m, 3), j4(m, 3))
        p = [0.0512_dp, 2.0e-4_dp, 5.0e-4_dp]
        call prob%residual_jacobian(p, r1, j1, st)
        call t%check('sensitivities: reuse: the first point, its Jacobian computed'// &
                     msg_of(st), st%code == 0 .and. prob%runs%jac_fresh)
        ! what the estimator does after each evaluation: tell the problem its gain
        call prob%note_gain(gauss_newton_gain(r1, j1))
        p(1) = p(1)*(1.0_dp + 1.0e-5_dp)
        call prob%residual_jacobian(p, r2, j2, st)
        call t%check('sensitivities: reuse: a short step on takes the Jacobian again'// &
                     msg_of(st), st%code == 0 .and. .not. prob%runs%jac_fresh .and. all(j2 == j1))
        call t%check('sensitivities: reuse: ... with residuals of its own', &
                     maxval(abs(r2 - r1)) > 0.0_dp)
        call fresh_jacobian(prob, p, r3, j3, st)
        call t%check('sensitivities: reuse: fresh_jacobian computes it at the point'// &
                     msg_of(st), st%code == 0 .and. prob%runs%jac_fresh .and. &
                     maxval(abs(j3 - j1)) > 0.0_dp)
        call other%residual_jacobian(p, r4, j4, st)
        call t%check_close('sensitivities: reuse: = the Jacobian a new problem computes there', &
                           1.0_dp + maxval(abs(j3 - j4))/maxval(abs(j4)), 1.0_dp, 1.0e-12_dp)
        call t%check('sensitivities: reuse: the same residuals', all(r3 == r2) .and. &
                     all(r4 == r2))
    end subroutine test_jacobian_reuse

    !> input/identify_record.nml estimating I1, c_v and c_q, and the first 10 s of its record
    !! (ok: both read; the check is labelled with `what`).
    subroutine first_ten_seconds(t, what, d, part, ok)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: what
        type(deck_t), intent(out) :: d
        type(record_t), intent(out) :: part
        logical, intent(out) :: ok
        type(record_t) :: rec
        type(status_t) :: st
        integer :: n
        call read_deck('input/identify_record.nml', d, st)
        if (st%code == 0) call read_record(d, rec, st)
        ok = st%code == 0
        call t%check('sensitivities: '//what//': the deck and record'//msg_of(st), ok)
        if (.not. ok) return
        d%measurement%estimate = 'I1 c_v c_q'
        n = count(rec%t <= rec%t(1) + 10.0_dp)
        part = rec
        part%t = rec%t(1:n)
        part%v = rec%v(1:n)
        if (rec%has_u) part%u = rec%u(1:n)
    end subroutine first_ten_seconds

    !> The largest distance from a multiplier of a to the nearest of b, relative to
    !! max(1, |b|) (the sets, whatever the order of a conjugate pair or of equal moduli).
    pure real(dp) function set_distance(a, b) result(e)
        complex(dp), intent(in) :: a(:), b(:)
        integer :: i
        e = 0.0_dp
        do i = 1, size(a)
            e = max(e, minval(abs(b - a(i))/max(1.0_dp, abs(b))))
        end do
        do i = 1, size(b)
            e = max(e, minval(abs(a - b(i))/max(1.0_dp, abs(b(i)))))
        end do
    end function set_distance

    !> ': the message' of a failed status, '' of a good one (for a check's label).
    function msg_of(stat) result(m)
        type(status_t), intent(in) :: stat
        character(len=:), allocatable :: m
        m = ''
        if (stat%code /= 0) m = ': '//msg_of_(stat)
    end function msg_of

end module test_sensitivities
