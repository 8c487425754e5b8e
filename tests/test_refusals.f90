!> Measurement inputs that gave a wrong number, a wrong uncertainty or a message naming the
!! wrong cause, through the executable of the build under test (each part holds in both
!! builds): the budget of a release of many timings (linear in the timings, against refits
!! of the inversion), an asymmetric rig timed over several cycles, the messages of tables,
!! platforms, plans and records, and fits whose result their own u swallows.
module test_refusals
    use kinds, only: dp
    use status, only: status_t
    use output_io, only: read_kv
    use testing, only: tester_t, write_text, exists, file_has, count_lines, run, scratch_dir, &
                       fresh_dir, empty_dir, abs_path
    use text, only: itoa
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, accuracy_of, start_of
    use period_inversion, only: input_u_t, period_fit_t, torsion_period_s, invert_periods, &
                                period_budget
    use record_fit, only: record_model
    implicit none
    private

    public :: run_refusals_tests

    character(len=*), parameter :: SCR = 'build/test_refusals'

contains

    subroutine run_refusals_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCR)
        if (t%want('refusals: the budget of the timings, linear, against refits')) &
            call test_budget_refits(t)
        if (t%want('refusals: one release of many timings, its budget by differences')) &
            call test_many_timings(t, exe)
        if (t%want('refusals: an asymmetric rig timed over ten cycles')) &
            call test_asymmetric_cycles(t, exe)
        if (t%want('refusals: calibrate on an asymmetric rig timed over ten cycles')) &
            call test_calibrate_cycles(t, exe)
        if (t%want('refusals: messages that name the cause')) call test_messages(t, exe)
        if (t%want('refusals: no result that its own u swallows')) call test_undetermined(t, exe)
        if (t%want('refusals: a track''s record_scale in mm/px: exit 3 naming record_scale')) &
            call test_track_scale(t, exe)
        if (t%want('refusals: a body off the axis slackens a cable: the offset''s limit')) &
            call test_offset_limit(t, exe)
    end subroutine run_refusals_tests

    !> The rig of input/identify_periods.nml (its true I1 0.0512).
    function lab_rig() result(d)
        type(deck_t) :: d
        d%path = 'lab_rig.nml'
        d%name = 'lab_rig'
        d%suspension%b = 0.4_dp
        d%suspension%b_prime = 0.4_dp
        d%suspension%l = 1.2_dp
        d%suspension%l_prime = 1.2_dp
        d%suspension%g = 9.80665_dp
        d%body%mass = 3.1_dp
        d%body%inertia = [0.045_dp, 0.063_dp, 0.0304_dp]
        d%body%r = 0.25_dp
        d%body%lambda = atan2(0.15_dp, 0.2_dp)
    end function lab_rig

    !> The budget's rows of the periods and amplitudes (the fit's linearised normal equation)
    !! against whole refits of the inversion with one period, or one amplitude, moved: four
    !! periods that scatter about the model at 10 to 60 degrees, with their u.  The rows
    !! leave out the residuals times the second derivatives (the periods' rows agree to
    !! 1e-3; they do to 3e-5) and the change of each period's weight with its amplitude
    !! (through dT/dA u_amplitude: the amplitudes' rows agree to 5e-2; they do to 2e-2).
    subroutine test_budget_refits(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(period_fit_t) :: f, f2
        type(status_t) :: st
        type(input_u_t) :: u
        real(dp) :: tp(4), a(4), pp(4), aa(4), ip, im, h, c
        integer :: i, k
        logical :: ok_t, ok_a
        d = lab_rig()
        a = [10.0_dp, 30.0_dp, 45.0_dp, 60.0_dp]
        do i = 1, 4
            call torsion_period_s(rig_of(d), 0.0512_dp, a(i), tp(i), st)
        end do
        tp = tp + [3.0e-4_dp, -2.0e-4_dp, 1.0e-4_dp, -1.5e-4_dp]
        u = input_u_t(mass=0.001_dp, l=0.001_dp, l_prime=0.001_dp, b=0.0005_dp, &
                      b_prime=0.0005_dp, g=0.0_dp, period=1.0e-4_dp, amplitude=0.5_dp)
        call invert_periods(rig_of(d), accuracy_of(d), tp, a, u, f, st)
        if (st%code == 0) call period_budget(rig_of(d), accuracy_of(d), tp, a, u, f, st)
        call t%check('budget refits: computed', st%code == 0)
        if (st%code /= 0) return
        ok_t = .true.
        ok_a = .true.
        d%body%inertia(1) = f%i1
        do i = 1, 4
            ! a period moved
            h = 1.0e-6_dp*tp(i)
            pp = tp
            pp(i) = tp(i) + h
            call invert_periods(rig_of(d), accuracy_of(d), pp, a, u, f2, st)
            ip = f2%i1
            pp(i) = tp(i) - h
            if (st%code == 0) call invert_periods(rig_of(d), accuracy_of(d), pp, a, u, f2, st)
            im = f2%i1
            c = (ip - im)/(2*h)
            k = row_of(f, 'period('//itoa(i)//')')
            if (k == 0 .or. st%code /= 0) then
                ok_t = .false.
            else
                ok_t = ok_t .and. abs(f%budget(k)%sensitivity - c) <= 1.0e-3_dp*abs(c)
            end if
            ! an amplitude moved
            h = 1.0e-3_dp
            aa = a
            aa(i) = a(i) + h
            call invert_periods(rig_of(d), accuracy_of(d), tp, aa, u, f2, st)
            ip = f2%i1
            aa(i) = a(i) - h
            if (st%code == 0) call invert_periods(rig_of(d), accuracy_of(d), tp, aa, u, f2, st)
            im = f2%i1
            c = (ip - im)/(2*h)
            k = row_of(f, 'amplitude('//itoa(i)//')')
            if (k == 0 .or. st%code /= 0) then
                ok_a = .false.
            else
                ok_a = ok_a .and. abs(f%budget(k)%sensitivity - c) <= 5.0e-2_dp*abs(c)
            end if
        end do
        call t%check('budget refits: dI1/dT_i of each period as its refit gives it (1e-3)', &
                     ok_t)
        call t%check('budget refits: dI1/dA_i of each amplitude as its refit gives it (5e-2)', &
                     ok_a)
    end subroutine test_budget_refits

    !> The row of the budget named nm (0: none).
    integer function row_of(f, nm) result(k)
        type(period_fit_t), intent(in) :: f
        character(len=*), intent(in) :: nm
        do k = 1, size(f%budget)
            if (trim(f%budget(k)%input) == nm) return
        end do
        k = 0
    end function row_of

    !> One release of 60 timings at one amplitude (a table of releases under one label):
    !! the sum of its amplitude rows' sensitivities is dI1/dA for all amplitudes moved
    !! together, and the sum of its period rows' that for all totals moved together: both
    !! against differences of the whole program's I1 (a refit per timing lost the amplitude
    !! rows of many timings in its own convergence test: they came out 0).
    subroutine test_many_timings(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, x
        real(dp) :: s_amp, s_per, i_ap, i_am, i_tp, i_tm, ha, ht
        integer :: e(5)
        d = SCR//'/many'
        x = abs_path(exe)
        call fresh_dir(d)
        ha = 0.05_dp
        ht = 0.01_dp
        call table(d//'/t0.csv', 0.0_dp, 0.0_dp)
        call table(d//'/ap.csv', ha, 0.0_dp)
        call table(d//'/am.csv', -ha, 0.0_dp)
        call table(d//'/tp.csv', 0.0_dp, ht)
        call table(d//'/tm.csv', 0.0_dp, -ht)
        e(1) = deck_run('t0')
        e(2) = deck_run('ap')
        e(3) = deck_run('am')
        e(4) = deck_run('tp')
        e(5) = deck_run('tm')
        call t%check('many timings: the five decks run (exit 0)', all(e == 0))
        if (any(e /= 0)) return
        call rows_sum(d//'/o/t0.identify', 'amplitude(', s_amp)
        call rows_sum(d//'/o/t0.identify', 'period(', s_per)
        i_ap = kv(d//'/o/ap.identify')
        i_am = kv(d//'/o/am.identify')
        i_tp = kv(d//'/o/tp.identify')
        i_tm = kv(d//'/o/tm.identify')
        call t%check('many timings: the amplitude rows are not 0', abs(s_amp) > 0.0_dp)
        call t%check_close('many timings: sum of the amplitude rows = dI1/dA of all', s_amp, &
                           (i_ap - i_am)/(2*ha), rtol=2.0e-2_dp)
        ! each total is of 10 cycles: a shift ht of every total moves each period ht/10
        call t%check_close('many timings: sum of the period rows = dI1/dT of all', s_per, &
                           (i_tp - i_tm)/(2*ht/10.0_dp), rtol=2.0e-3_dp)
    contains
        subroutine table(path, da, dt)
            character(len=*), intent(in) :: path
            real(dp), intent(in) :: da, dt
            character(len=:), allocatable :: s
            character(len=40) :: row
            integer :: k
            s = 'trial,l,l_prime,period,cycles,amplitude'//new_line('a')
            do k = 1, 60
                write (row, '(a,f0.4,a,f0.4)') 'a,1.2,1.2,', 18.34_dp + 0.01_dp*mod(7*k, 11) - &
                    0.05_dp + dt, ',10,', 10.0_dp + da
                s = s//trim(row)//new_line('a')
            end do
            call write_text(path, s)
        end subroutine table
        integer function deck_run(nm)
            character(len=*), intent(in) :: nm
            call write_text(d//'/'//nm//'.nml', "&scene title = 'many timings', analyses = "// &
                "'identify' /"//new_line('a')//'&suspension b = 0.25, b_prime = 0.25, '// &
                'l = 1.2, l_prime = 1.2, g = 9.80665 /'//new_line('a')//'&body mass = 8.1, '// &
                'inertia = 0.09, 0.0286875, 0.0624375, cg_depth = 0.025 /'//new_line('a')// &
                "&measurement trials = '"//nm//".csv', u_period = 0.05, u_mass = 0.005, "// &
                'u_amplitude = 1.0 /'//new_line('a'))
            deck_run = run('cd '//d//' && timeout 120 '//x//' '//nm//'.nml --out o', d)
        end function deck_run
        real(dp) function kv(path)
            character(len=*), intent(in) :: path
            logical :: found
            call read_kv(path, 'I1', kv, found)
        end function kv
    end subroutine test_many_timings

    !> The sum of the sensitivities of the budget rows of path whose name starts with head.
    subroutine rows_sum(path, head, s)
        character(len=*), intent(in) :: path, head
        real(dp), intent(out) :: s
        character(len=512) :: line
        character(len=40) :: nm
        real(dp) :: v(4)
        integer :: u, ios
        s = 0.0_dp
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, head) /= 1) cycle
            read (line, *, iostat=ios) nm, v
            if (ios == 0) s = s + v(3)
        end do
        close (u)
    end subroutine rows_sum

    !> Unequal cables (l = 1.2, l' = 1.0) and a mass centre off the bisector (cg_offset =
    !! 0.02): the total of ten cycles from the release, read off the program's own
    !! simulation (the tenth maximum of theta4 after it swung below 0), gives I1 back to
    !! 1e-4 (it gave -7.4 % with exit 0 when the model's first period was taken ten times).
    !! A rig whose torsion feeds its tilt and sway until theta4 returns below 0 is refused
    !! over ten cycles (exit 4), with one line.
    subroutine test_asymmetric_cycles(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, x
        character(len=32) :: buf
        real(dp) :: total, i1
        integer :: e, nmax
        logical :: found
        d = SCR//'/asym'
        x = abs_path(exe)
        call fresh_dir(d)
        call write_text(d//'/truth.nml', "&scene title = 'truth', analyses = 'simulate' /"// &
            new_line('a')//'&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.00, '// &
            'g = 9.80665 /'//new_line('a')//'&body mass = 3.10, inertia = 0.0512, 0.0630, '// &
            '0.0304, cg_depth = 0.15, cg_offset = 0.02 /'//new_line('a')//"&start mode = "// &
            "'raised', amplitude = 10.0 /"//new_line('a')//'&integration tau_end = 90.0, '// &
            'dtau_out = 0.002, rtol = 1e-12, atol = 1e-14 /'//new_line('a'))
        e = run('cd '//d//' && '//x//' truth.nml --out o', d)
        call tenth_maximum(d//'/o/truth.dat', sqrt(0.4_dp/9.80665_dp), total, nmax)
        call t%check('asymmetric: the simulation shows ten maxima (exit '//itoa(e)//')', &
                     e == 0 .and. nmax >= 10)
        if (nmax < 10) return
        write (buf, '(f0.7)') total
        call write_text(d//'/id.nml', "&scene title = 'asym', analyses = 'identify' /"// &
            new_line('a')//'&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.00, '// &
            'g = 9.80665 /'//new_line('a')//'&body mass = 3.10, inertia = 0.045, 0.0630, '// &
            '0.0304, cg_depth = 0.15, cg_offset = 0.02 /'//new_line('a')//'&measurement '// &
            'periods = '//trim(buf)//', cycles = 10, amplitudes = 10, u_period = 1e-3 /'// &
            new_line('a'))
        e = run('cd '//d//' && timeout 120 '//x//' id.nml --out o', d)
        call read_kv(d//'/o/id.identify', 'I1', i1, found)
        call t%check('asymmetric: ten cycles timed: exit 0 (got '//itoa(e)//')', e == 0 .and. &
                     found)
        call t%check_close('asymmetric: ten cycles timed: I1 back to 1e-4', i1, 0.0512_dp, &
                           rtol=1.0e-4_dp)
        ! the template's frame on unequal cables: its returns are not countable
        call execute_command_line("sed -e 's/l_prime = 1.0/l_prime = 1.2/' "// &
            'input/measure_template.nml > '//d//'/irregular.nml')
        call fresh_dir(d//'/o2')
        e = run('cd '//d//' && timeout 120 '//x//' irregular.nml --out o2', d)
        call t%check('asymmetric: returns that cannot be counted: exit 4 (got '//itoa(e)// &
                     '), one line, no file', all([e == 4, count_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'cannot be counted'), empty_dir(d//'/o2')]))
    end subroutine test_asymmetric_cycles

    !> Calibrate on the rig of test_asymmetric_cycles (l = 1.2, l' = 1.0, cg_offset =
    !! 0.02), a reference of known I1 = 0.0512 timed over ten cycles from releases at 8 and
    !! 10 degrees (the totals read off the program's own simulations of the true rig, the
    !! tenth maximum): the scale of b b' is the truth 1 within 3e-4 (the calibration fitted
    !! the model's first period ten times: the scale 2.6 % off, exit 0).  A total over 300
    !! cycles (more than the model counts on such a rig) is refused with one line.
    subroutine test_calibrate_cycles(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: RIG = '&suspension b = 0.40, b_prime = 0.40, '// &
            'l = 1.20, l_prime = 1.00, g = 9.80665 /'//new_line('a')//'&body mass = 3.10, '// &
            'inertia = 0.0512, 0.0630, 0.0304, cg_depth = 0.15, cg_offset = 0.02 /'// &
            new_line('a')
        character(len=:), allocatable :: d, x
        character(len=32) :: buf(2)
        real(dp), parameter :: AMPS(2) = [8.0_dp, 10.0_dp]
        real(dp) :: total, scale
        integer :: e, nmax, k
        logical :: found
        d = SCR//'/calasym'
        x = abs_path(exe)
        call fresh_dir(d)
        do k = 1, 2
            write (buf(k), '(f0.1)') AMPS(k)
            call write_text(d//'/truth.nml', "&scene title = 'truth', analyses = "// &
                "'simulate' /"//new_line('a')//RIG//"&start mode = 'raised', amplitude = "// &
                trim(buf(k))//' /'//new_line('a')//'&integration tau_end = 90.0, '// &
                'dtau_out = 0.002, rtol = 1e-12, atol = 1e-14 /'//new_line('a'))
            e = run('cd '//d//' && '//x//' truth.nml --out o', d)
            call tenth_maximum(d//'/o/truth.dat', sqrt(0.4_dp/9.80665_dp), total, nmax)
            call t%check('calibrate cycles: the simulation at '//trim(buf(k))//' deg shows '// &
                         'ten maxima (exit '//itoa(e)//')', e == 0 .and. nmax >= 10)
            if (nmax < 10) return
            write (buf(k), '(f0.7)') total
        end do
        call write_text(d//'/cal.nml', "&scene title = 'cal', analyses = 'calibrate' /"// &
            new_line('a')//RIG//'&measurement periods = '//trim(buf(1))//', '// &
            trim(buf(2))//', cycles = 10, amplitudes = 8, 10, u_period = 1e-3 /'// &
            new_line('a')//'&calibration reference_I1 = 0.0512 /'//new_line('a'))
        e = run('cd '//d//' && timeout 300 '//x//' cal.nml --out o', d)
        call read_kv(d//'/o/cal.calibration', 'scale', scale, found)
        call t%check('calibrate cycles: exit 0 (got '//itoa(e)//')', e == 0 .and. found)
        call t%check_close('calibrate cycles: the scale of b b'' is 1 within 3e-4', scale, &
                           1.0_dp, rtol=3.0e-4_dp)
        ! more cycles than the model counts on such a rig: refused, not counted as 200
        call write_text(d//'/many.nml', "&scene title = 'many', analyses = 'calibrate' /"// &
            new_line('a')//RIG//'&measurement periods = 420.0, 421.0, cycles = 300, '// &
            'amplitudes = 8, 10, u_period = 1e-3 /'//new_line('a')//'&calibration '// &
            'reference_I1 = 0.0512 /'//new_line('a'))
        call fresh_dir(d//'/o')
        e = run('cd '//d//' && timeout 300 '//x//' many.nml --out o', d)
        call t%check('calibrate cycles: 300 cycles on an asymmetric rig: exit '//itoa(e)// &
                     ' (want 2), one line naming cycles, no file', all([e == 2, &
                     count_lines(d//'/stderr') == 1, file_has(d//'/stderr', 'cycles'), &
                     empty_dir(d//'/o')]))
    end subroutine test_calibrate_cycles

    !> The time (s) of the tenth maximum of theta4 in a simulate .dat (columns tau, theta1
    !! .. theta5, their rates): each maximum a zero of theta4' from + to - after theta4 has
    !! been below 0, interpolated linearly between the rows; nmax the maxima found.
    subroutine tenth_maximum(path, tscale, total, nmax)
        character(len=*), intent(in) :: path
        real(dp), intent(in) :: tscale          !! seconds per unit of tau
        real(dp), intent(out) :: total
        integer, intent(out) :: nmax
        character(len=1024) :: line
        real(dp) :: r0(11), r1(11)
        integer :: u, ios
        logical :: below, have
        total = 0.0_dp
        nmax = 0
        below = .false.
        have = .false.
        r0 = 0.0_dp
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#') cycle
            read (line, *, iostat=ios) r1
            if (ios /= 0) exit
            if (have) then
                if (.not. below) then
                    below = r1(5) < 0.0_dp
                else if (r0(10) > 0.0_dp .and. r1(10) <= 0.0_dp) then
                    nmax = nmax + 1
                    below = .false.
                    if (nmax == 10) then
                        total = (r0(1) + (r1(1) - r0(1))*r0(10)/(r0(10) - r1(10)))*tscale
                        exit
                    end if
                end if
            end if
            r0 = r1
            have = .true.
        end do
        close (u)
    end subroutine tenth_maximum

    !> Each message names its cause, on one line, and leaves no file: an empty cell of a
    !! table of hangs's first row; a hang's period in microseconds; a table of releases
    !! without u_period (its warning names u_period); a plan of 13 hangs (one per axis: no
    !! hang with up -u beside up u) and of 14 (refused); u_l_prime on a platform; one
    !! record on two rows of a table; a mass column with tare_mass (the body's mass from
    !! the column, and a tare above it refused); a bound of u_amplitude in short form.
    subroutine test_messages(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, x
        real(dp) :: mb
        integer :: e
        logical :: found
        d = SCR//'/messages'
        x = abs_path(exe)
        call fresh_dir(d)
        call execute_command_line("sed 's/monte_carlo = 2000/monte_carlo = 0/' "// &
            'input/tensor_example.nml > '//d//'/t.nml; cp input/tensor_example_hangs.csv '// &
            d//'/good.csv')
        call execute_command_line("sed 's/^1,1,0,0,0,1,0,/1,1,,0,0,1,0,/' input/"// &
            'tensor_example_hangs.csv > '//d//'/tensor_example_hangs.csv')
        call refused('empty cell', 't.nml', 2, 'field 3 (up_y) is empty')
        call execute_command_line("sed 's/^2,0,1,0,0,0,1,16.159999340,/2,0,1,0,0,0,1,0.000016,"// &
            "/' input/tensor_example_hangs.csv > "//d//'/tensor_example_hangs.csv')
        call refused('period in microseconds', 't.nml', 2, 'a period in ms or us')
        ! without u_period: a warning naming u_period
        call execute_command_line("sed 's/u_period = 0.05, //' input/identify_trials.nml > "// &
            d//'/nou.nml; cp input/identify_trials.csv '//d)
        call fresh_dir(d//'/o')
        e = run('cd '//d//' && timeout 120 '//x//' nou.nml --out o', d)
        call t%check('messages: no u_period: exit 0, the warning names u_period', &
                     all([e == 0, file_has(d//'/stderr', 'u_period is not given')]))
        ! the plan: one hang per axis
        call execute_command_line('cp '//d//'/good.csv '//d//'/tensor_example_hangs.csv; '// &
            "sed 's/monte_carlo = 0/monte_carlo = 0, plan = 13/' "//d//'/t.nml > '//d// &
            '/p13.nml')
        call fresh_dir(d//'/o')
        e = run('cd '//d//' && timeout 120 '//x//' p13.nml --out o', d)
        call t%check('messages: plan = 13: exit 0, 13 hangs, no two on one axis', &
                     all([e == 0, one_per_axis(d//'/o/p13.plan.csv', 13)]))
        call execute_command_line("sed 's/monte_carlo = 0/monte_carlo = 0, plan = 27/' "// &
            d//'/t.nml > '//d//'/p27.nml')
        call refused('plan = 27', 'p27.nml', 2, 'plan = 27')
        ! a platform has no l_prime
        call execute_command_line("sed 's/u_l = 0.002,/u_l = 0.002, u_l_prime = 0.3,/' "// &
            'input/measure_platform_template.nml > '//d//'/plat.nml')
        call refused('platform u_l_prime', 'plat.nml', 2, 'u_l_prime = 0.3')
        ! one record on two rows
        call write_text(d//'/recs.csv', 'trial,record'//new_line('a')//'a,swing.dat'// &
                        new_line('a')//'b,swing.dat'//new_line('a'))
        call execute_command_line('cp input/identify_record_swing.dat '//d//'/swing.dat; '// &
            'sed "s/record = ''identify_record_swing.dat''/trials = ''recs.csv''/" '// &
            'input/identify_record.nml > '//d//'/recs.nml')
        call refused('a record twice', 'recs.nml', 2, 'the same record as line 2')
        ! a mass column with tare_mass: the body's mass from the column (8.1 - 1.0)
        call execute_command_line("sed -e 's/^trial.*/&,mass/' -e '/^l[0-9]/s/$/,8.1/' "// &
            'input/identify_trials.csv > '//d//'/tm.csv')
        call execute_command_line("sed -e 's/identify_trials.csv/tm.csv/' -e "// &
            "'s/mass = 8.1/mass = 9.0/' -e 's/u_cg_depth = 0.002/u_cg_depth = 0.002, "// &
            "tare_mass = 1.0/' input/identify_trials.nml > "//d//'/tm.nml')
        call fresh_dir(d//'/o')
        e = run('cd '//d//' && timeout 120 '//x//' tm.nml --out o', d)
        call read_kv(d//'/o/tm.identify', 'mass_body', mb, found)
        call t%check('messages: mass column, tare_mass: exit 0', e == 0 .and. found)
        call t%check_close('messages: mass_body = the column''s mass - tare_mass', mb, 7.1_dp, &
                           rtol=1.0e-12_dp)
        call execute_command_line("sed 's/tare_mass = 1.0/tare_mass = 8.5/' "//d//'/tm.nml > '// &
                                  d//'/tm2.nml')
        call refused('tare_mass above a release''s mass', 'tm2.nml', 2, 'column mass = 8.1')
        ! a bound computed from the deck's numbers, in short form (not 0.019999999999998862)
        call execute_command_line("sed 's/amplitudes = 10.0, 30.0, 60.0/amplitudes = 10.0, "// &
            "30.0, 179.9/' input/identify_periods.nml > "//d//'/ua.nml')
        call refused('u_amplitude bound', 'ua.nml', 2, 'u_amplitude < 0.02 for')
    contains
        subroutine refused(nm, deck_file, want, word)
            character(len=*), intent(in) :: nm, deck_file, word
            integer, intent(in) :: want
            integer :: ex
            call fresh_dir(d//'/o')
            ex = run('cd '//d//' && timeout 120 '//x//' '//deck_file//' --out o', d)
            call t%check('messages: '//nm//': exit '//itoa(ex)//' (want '//itoa(want)// &
                         '), one line saying "'//word//'", no file', all([ex == want, &
                         count_lines(d//'/stderr') == 1, file_has(d//'/stderr', word), &
                         empty_dir(d//'/o')]))
        end subroutine refused
    end subroutine test_messages

    !> The plan file holds n hangs and no two of their ups on one axis (u and -u).
    logical function one_per_axis(path, n) result(ok)
        character(len=*), intent(in) :: path
        integer, intent(in) :: n
        character(len=512) :: line
        real(dp) :: v(10), up(3, 100)
        integer :: u, ios, k, j, m
        ok = .false.
        m = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. line(1:4) == 'hang') cycle
            read (line, *, iostat=ios) v
            if (ios /= 0 .or. m == 100) exit
            m = m + 1
            up(:, m) = v(2:4)/norm2(v(2:4))
        end do
        close (u)
        if (m /= n) return
        do k = 1, m
            do j = 1, k - 1
                if (abs(dot_product(up(:, k), up(:, j))) > 1.0_dp - 1.0e-9_dp) return
            end do
        end do
        ok = .true.
    end function one_per_axis

    !> No result that its own u swallows: a light body (I1 = 2e-4 kg m^2 on the rig of
    !! input/identify_periods.nml, its period at 90 degrees near the rig's period with
    !! I1 -> 0) timed with u_period = 0.03 s, or with u_l = 0.23 m, is refused (exit 2,
    !! one line naming the budget's largest row); it printed I1 = 2.00034E-04 +- 6.5E-04
    !! with exit 0.  The same body with u_period = 1e-3 still gives its I1 (exit 0).
    subroutine test_undetermined(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, x, base
        integer :: e
        d = SCR//'/undetermined'
        x = abs_path(exe)
        call fresh_dir(d)
        base = "-e 's/periods = 1.41564, 1.44107, 1.52913/periods = 0.35284/' -e "// &
            "'s/amplitudes = 10.0, 30.0, 60.0/amplitudes = 90.0/' -e 's/monte_carlo = 2000/"// &
            "monte_carlo = 0/' -e 's/inertia = 0.045, 0.0630, 0.0304/inertia = 0.0003, "// &
            "0.0302, 0.0304/'"
        call light('timing', "-e 's/u_period = 1e-4/u_period = 3e-2/'", 2, 'period(1) =')
        call light('length', "-e 's/u_l = 0.001, u_l_prime = 0.001/u_l = 0.23, u_l_prime = "// &
                   "0.23/'", 2, 'l = 1.2')
        call light('resolved', "-e 's/u_period = 1e-4/u_period = 1e-3/'", 0, '')
    contains
        subroutine light(nm, sed, want, word)
            character(len=*), intent(in) :: nm, sed, word
            integer, intent(in) :: want
            call execute_command_line('sed '//base//' '//sed//' input/identify_periods.nml > '// &
                                      d//'/'//nm//'.nml')
            call fresh_dir(d//'/o')
            e = run('cd '//d//' && timeout 120 '//x//' '//nm//'.nml --out o', d)
            if (want == 0) then
                call t%check('undetermined: '//nm//': exit 0 (got '//itoa(e)//')', &
                             all([e == 0, exists(d//'/o/'//nm//'.identify')]))
            else
                call t%check('undetermined: '//nm//': exit '//itoa(e)//' (want '//itoa(want)// &
                             '), one line naming '//word//', no file', all([e == want, &
                             count_lines(d//'/stderr') == 1, file_has(d//'/stderr', &
                             'does not determine I1'), file_has(d//'/stderr', word), &
                             empty_dir(d//'/o')]))
            end if
        end subroutine light
    end subroutine test_undetermined

    !> A video track (made here: the model's point 5 cm off the axis seen from below, 0.505
    !! mm a px, the camera's origin at (640, 360) px, no noise) fitted for I1 and the
    !! origin: with record_scale = 5.05e-4 (m/px) it gives I1 back to 1e-4 (exit 0); with
    !! record_scale = 0.505 (the scale in mm/px) the fit fails (exit 3) with one line that
    !! names record_scale = 0.505, gives the residual in m (and px) and no file.
    subroutine test_track_scale(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: N = 601
        real(dp), parameter :: SCALE = 5.05e-4_dp, ORIGIN(2) = [640.0_dp, 360.0_dp]
        real(dp), parameter :: QV(3) = [0.0_dp, 0.05_dp, 0.0_dp]
        type(deck_t) :: truth
        type(status_t) :: stat
        real(dp) :: tt(N), vals(2*N), i1
        character(len=:), allocatable :: d, x, text, head, deck
        character(len=80) :: line
        integer :: i, e
        logical :: found
        d = SCR//'/track'
        x = abs_path(exe)
        call fresh_dir(d)
        head = "&scene title = 'track', analyses = 'identify' /"//new_line('a')// &
            '&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.20, g = 9.80665 /'// &
            new_line('a')//'&body mass = 3.10, inertia = '
        deck = ', 0.0630, 0.0304, r = 0.20, lambda = 0.0 /'//new_line('a')//'&integration '// &
            'rtol = 1e-10, atol = 1e-12 /'//new_line('a')//"&start mode = 'raised', "// &
            'amplitude = 20.0 /'//new_line('a')
        ! the track of the true rig (I1 = 0.0512) in px
        call write_text(d//'/truth.nml', head//'0.0512'//deck)
        call read_deck(d//'/truth.nml', truth, stat)
        if (stat%code == 0) call record_model(rig_of(truth), start_of(truth), &
            accuracy_of(truth), [((i - 1)/60.0_dp, i=1, N)], 0.0_dp, .false., vals, stat, &
            point=QV)
        call t%check('track: the track made', stat%code == 0)
        if (stat%code /= 0) return
        text = 't (s), x (px), y (px)'//new_line('a')
        do i = 1, N
            tt(i) = (i - 1)/60.0_dp
            write (line, '(es23.15,2(", ",f0.6))') tt(i), vals(i)/SCALE + ORIGIN(1), &
                vals(N + i)/SCALE + ORIGIN(2)
            text = text//trim(line)//new_line('a')
        end do
        call write_text(d//'/track.dat', text)
        ! the fit from I1 2 % off
        deck = head//'0.0502'//deck//"&measurement "// &
            "record = 'track.dat', quantity = 'point', record_point = 0, 0.05, 0, "// &
            "estimate = 'I1 bias', record_scale = "
        call write_text(d//'/right.nml', deck//'5.05e-4 /'//new_line('a'))
        call write_text(d//'/mm.nml', deck//'0.505 /'//new_line('a'))
        e = run('cd '//d//' && timeout 300 '//x//' right.nml --out o', d)
        call read_kv(d//'/o/right.identify', 'I1', i1, found)
        call t%check('track: record_scale in m/px: exit 0 (got '//itoa(e)//')', &
                     e == 0 .and. found)
        call t%check_close('track: record_scale in m/px: I1 back to 1e-4', i1, 0.0512_dp, &
                           rtol=1.0e-4_dp)
        call fresh_dir(d//'/o')
        e = run('cd '//d//' && timeout 300 '//x//' mm.nml --out o', d)
        call t%check('track: record_scale in mm/px: exit '//itoa(e)//' (want 3), one line '// &
                     'naming record_scale = 0.505, the residual in m and px, no file', &
                     all([e == 3, count_lines(d//'/stderr') == 1, &
                          file_has(d//'/stderr', 'record_scale = 0.505 m'), &
                          file_has(d//'/stderr', ' m, '), file_has(d//'/stderr', ' px)'), &
                          .not. file_has(d//'/stderr', ' rad'), empty_dir(d//'/o')]))
    end subroutine test_track_scale

    !> A body off the axis of a regular platform of n cables (R = R' = 0.135 m, vertical
    !! cables) beyond where a cable goes slack at rest: exit 2, one line naming cg_offset as
    !! given and the offset at which the cable goes slack, against the statics: n = 3
    !! (inextensible, determinate) the cables hold the mass centre up to the vertex it
    !! moves to, R; n >= 4 (stiff elastic cables, the level body's stretches a plane) the
    !! tensions T_i = (m g/n)(1 + 2 r.p_i/R^2), so along x the limit is R/(2 max(-cos a_i)),
    !! R/2 for n = 4 (cable 3, at 180 degrees), R/(2 cos 36 degrees) for n = 5 (cables 3
    !! and 4).  Within 1e-3 (the elastic body tilts by its stretches).  Within the limit
    !! (0.05) the run goes (exit 0).
    subroutine test_offset_limit(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp), parameter :: R = 0.135_dp, PI_ = 3.14159265358979324_dp
        character(len=:), allocatable :: d, x
        d = SCR//'/offset'
        x = abs_path(exe)
        call fresh_dir(d)
        call slack(3, '0.14', R, 2, 3)
        call slack(4, '0.1', 0.5_dp*R, 3, 3)
        call slack(5, '0.1', 0.5_dp*R/cos(PI_/5.0_dp), 3, 4)
        call slack(4, '0.05', -1.0_dp, 0, 0)
    contains
        !> n cables, cg_offset = off, 0: refused naming lim (> 0) and cable c1 or c2 (that
        !! go slack together), or run (lim < 0).
        subroutine slack(n, off, lim, c1, c2)
            integer, intent(in) :: n, c1, c2
            character(len=*), intent(in) :: off
            real(dp), intent(in) :: lim
            character(len=:), allocatable :: nm
            real(dp) :: got
            integer :: e
            nm = 'n'//itoa(n)//'_'//off
            call write_text(d//'/'//nm//'.nml', "&scene analyses = 'simulate' /"// &
                new_line('a')//'&suspension cables = '//itoa(n)//', radius = 0.135, '// &
                'radius_prime = 0.135, l = 1.0, g = 9.81 /'//new_line('a')//'&body mass = '// &
                '0.869, inertia = 0.0093, 0.0050, 0.0050, cg_offset = '//off//', 0 /'// &
                new_line('a')//'&integration tau_end = 0.1, dtau_out = 0.02 /'//new_line('a'))
            call fresh_dir(d//'/o')
            e = run('cd '//d//' && timeout 120 '//x//' '//nm//'.nml --out o', d)
            if (lim < 0.0_dp) then
                call t%check('offset: '//itoa(n)//' cables, cg_offset = '//off//': exit 0 '// &
                             '(got '//itoa(e)//')', e == 0)
                return
            end if
            got = number_after(d//'/stderr', 'slack beyond cg_offset = ')
            call t%check('offset: '//itoa(n)//' cables, cg_offset = '//off//': exit '// &
                         itoa(e)//' (want 2), one line naming cg_offset and cable '//itoa(c1)// &
                         ', no file', all([e == 2, count_lines(d//'/stderr') == 1, &
                         file_has(d//'/stderr', 'cg_offset = '//off//', 0:'), &
                         any([file_has(d//'/stderr', 'cable '//itoa(c1)//' is slack'), &
                              file_has(d//'/stderr', 'cable '//itoa(c2)//' is slack')]), &
                         empty_dir(d//'/o')]))
            call t%check_close('offset: '//itoa(n)//' cables: the limit against the statics', &
                               got, lim, rtol=1.0e-3_dp)
        end subroutine slack
    end subroutine test_offset_limit

    !> The number that follows key on the first line of path holding it (-1 when none).
    real(dp) function number_after(path, key) result(v)
        character(len=*), intent(in) :: path, key
        character(len=4096) :: line
        integer :: u, ios, j, k
        v = -1.0_dp
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            j = index(line, key)
            if (j == 0) cycle
            j = j + len(key)
            k = scan(line(j:), ', ;)')
            if (k == 0) k = len_trim(line(j:)) + 1
            read (line(j:j + k - 2), *, iostat=ios) v
            if (ios /= 0) v = -1.0_dp
            exit
        end do
        close (u)
    end function number_after

end module test_refusals
