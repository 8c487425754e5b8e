!> make_record: measurements made by the program itself, for the example decks of the
!! identify analysis and their tests (Makefile target `records`).
!!
!!   make_record record DECK DURATION RATE SIGMA SEED QUANTITY OUT
!!       simulate DECK (the true rig, with its &damping) from its &start, sample theta4
!!       (QUANTITY = angle, rad) or W = omega . n3 (rate, rad/s) every 1/RATE s up to
!!       DURATION s, add normal noise of standard deviation SIGMA from stream 0 of SEED, and
!!       write the record OUT (module identify's make_record).
!!   make_record periods DECK SIGMA SEED A1 [A2 ...]
!!       print '&measurement'-ready lines: the periods (s) of DECK's rig at peak amplitudes
!!       A1, A2, ... degrees (period_inversion's rig_period_s: exact torsion, or simulated)
!!       plus normal noise of standard deviation SIGMA (s) from stream 0 of SEED, rounded
!!       to 1e-5 s.
!!   make_record trials DECK OUT SEED SIGMA SCATTER RELEASES TIMINGS CYCLES AMP L1 [L2 ...]
!!       write OUT, a table of releases (&measurement trials): for each cable length L
!!       (l = l_prime = L), RELEASES releases, each of the rig's I1 times (1 + SCATTER z)
!!       (what changes between releases), timed TIMINGS times over CYCLES cycles at
!!       amplitude AMP degrees, each total with normal noise SIGMA (s) and rounded to
!!       0.01 s (a stopwatch); z and the noise from stream 0 of SEED.
!!   make_record hangs DECK SIGMA SEED OUT
!!       the table of hangs of DECK's &tensor hangs (its periods are not read) with each
!!       row's period made by the model of that hang (module hang_model: the torsion mode at
!!       amplitude 0, else the full model at the row's amplitude) for the body whose
!!       principal moments are DECK's &body inertia and whose principal axes are the rows
!!       of DECK's &body btilde in the body frame: cycles times the period plus normal
!!       noise of standard deviation SIGMA (s) from stream 0 of SEED, to 1e-9 s; written to
!!       OUT as a comma-separated table with the input's columns (analysis tensor's
!!       example).
!! Exit status 0, or 2 with one line on standard error.
program make_record_main
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: iso_fortran_env, only: error_unit
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use record_fit, only: make_record
    use period_inversion, only: rig_period_s
    use deck_runs, only: rig_of, start_of, accuracy_of
    use random, only: rng_t, rng_stream, rng_normal
    use text, only: fixed, itoa, rshort
    use output_io, only: out_files_t
    use tables, only: table_t, read_table
    use measurement, only: measurement_t
    use measurement_read, only: read_hangs
    use hang_model, only: hang_rig, hang_period, tensor_entries
    use tensor_fit, only: tensor_problem_t, problem_of, model_periods
    use rig, only: rig_t
    implicit none
    interface
        !> C library exit(3) (as bifilar: no ERROR STOP line from the run-time library).
        subroutine c_exit(status) bind(C, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
    end interface
    character(len=1024) :: mode, arg
    type(deck_t) :: d
    type(status_t) :: st
    type(rng_t) :: g
    real(dp) :: duration, rate, sigma, a, tp
    real(dp), allocatable :: amps(:), per(:)
    integer :: seed, k, na, ios, nrel, ntime, r, j, u
    real(dp) :: scatter, cycles, len_k, i1r
    character(len=:), allocatable :: line1, line2, out
    type(out_files_t) :: files
    if (command_argument_count() < 5) call usage()
    call get_command_argument(1, mode)
    call get_command_argument(2, arg)
    call read_deck(trim(arg), d, st)
    if (st%code /= 0) call fail(trim(arg)//': '//st%msg)
    select case (trim(mode))
    case ('record')
        if (command_argument_count() /= 8) call usage()
        duration = real_arg(3)
        rate = real_arg(4)
        sigma = real_arg(5)
        seed = nint(real_arg(6))
        call get_command_argument(7, arg)
        if (trim(arg) /= 'angle' .and. trim(arg) /= 'rate') call usage()
        mode = arg
        call get_command_argument(8, arg)
        call make_record(rig_of(d), start_of(d), accuracy_of(d), d%scene%title, d%path, duration, &
                         rate, sigma, seed, trim(mode), trim(arg), st)
        if (st%code /= 0) call fail(st%msg)
    case ('periods')
        sigma = real_arg(3)
        seed = nint(real_arg(4))
        na = command_argument_count() - 4
        allocate (amps(na), per(na))
        g = rng_stream(seed, 0)
        line1 = '             periods ='
        line2 = '             amplitudes ='
        do k = 1, na
            a = real_arg(4 + k)
            call rig_period_s(rig_of(d), accuracy_of(d), d%body%inertia(1), a, tp, st)
            if (st%code /= 0) call fail(st%msg)
            tp = anint((tp + sigma*rng_normal(g))*1.0e5_dp)/1.0e5_dp
            line1 = line1//' '//fixed(tp, 5)//','
            line2 = line2//' '//fixed(a, 1)//','
        end do
        write (*, '(a)') line1
        write (*, '(a)') line2
    case ('trials')
        if (command_argument_count() < 11) call usage()
        call get_command_argument(3, arg)
        out = trim(arg)
        seed = nint(real_arg(4))
        sigma = real_arg(5)
        scatter = real_arg(6)
        nrel = nint(real_arg(7))
        ntime = nint(real_arg(8))
        cycles = real_arg(9)
        a = real_arg(10)
        g = rng_stream(seed, 0)
        call files%open(out, u, st)
        if (st%code /= 0) call fail(st%msg)
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar make_record trials: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# each release''s I1 scattered by '// &
            fixed(100*scatter, 2)//' %, timings +- '//fixed(sigma, 3)//' s, seed '//itoa(seed)
        if (ios == 0) write (u, '(a)', iostat=ios) 'trial,l,l_prime,period,cycles,amplitude'
        do k = 11, command_argument_count()
            len_k = real_arg(k)
            d%suspension%l = len_k
            d%suspension%l_prime = len_k
            do r = 1, nrel
                i1r = d%body%inertia(1)*(1.0_dp + scatter*rng_normal(g))
                call rig_period_s(rig_of(d), accuracy_of(d), i1r, a, tp, st, cycles)
                if (st%code /= 0) call fail(st%msg)
                do j = 1, ntime
                    if (ios == 0) write (u, '(a)', iostat=ios) 'l'//fixed(len_k, 2)//'-'// &
                        itoa(r)//','//fixed(len_k, 4)//','//fixed(len_k, 4)//','// &
                        fixed(anint((cycles*tp + sigma*rng_normal(g))*100.0_dp)/100.0_dp, 2)// &
                        ','//itoa(nint(cycles))//','//fixed(a, 1)
                end do
            end do
        end do
        call files%close(u, ios, st)
        if (st%code == 0) call files%commit(st)
        if (st%code /= 0) call fail(st%msg)
    case ('hangs')
        if (command_argument_count() /= 5) call usage()
        sigma = real_arg(3)
        seed = nint(real_arg(4))
        call get_command_argument(5, arg)
        call make_hangs(trim(arg))
    case default
        call usage()
    end select
contains
    !> The hangs table of d with the periods of the body of &body inertia and btilde.
    subroutine make_hangs(out)
        character(len=*), intent(in) :: out
        type(table_t) :: tab
        type(measurement_t) :: set
        type(rig_t) :: rg
        real(dp) :: x(6), jt(3, 3), tp
        real(dp), allocatable :: tc(:)
        type(tensor_problem_t) :: prob
        integer :: i, k, u, c_per
        character(len=:), allocatable :: row
        call read_hangs(d%tensor, d%suspension, d%body, set, st)
        if (st%code /= 0) call fail(st%msg)
        call read_table(d%tensor%hangs_path, tab, st)
        if (st%code /= 0) call fail(st%msg)
        ! J = sum_i I_i b_i b_i^T, b_i the rows of btilde (body frame)
        jt = 0.0_dp
        do k = 1, 3
            jt = jt + d%body%inertia(k)*spread(d%body%btilde(k, :), 2, 3)* &
                spread(d%body%btilde(k, :), 1, 3)
        end do
        x = tensor_entries(jt)
        if (d%tensor%has_fixture()) then
            ! what hangs: the body with its fixture (a platform's own mass and inertia)
            call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set, prob)
            allocate (tc(size(prob%case_hang)))
            call model_periods(prob, x, tc, st)
            if (st%code /= 0) call fail(st%msg)
        end if
        c_per = tab%column('period')
        g = rng_stream(seed, 0)
        open (newunit=u, file=out, status='replace', action='write', iostat=ios)
        if (ios /= 0) call fail('cannot write '//out)
        write (u, '(a)') '# made by bin/make_record hangs '//trim(d%path)//' '// &
            rshort(sigma)//' '//itoa(seed)//' (the periods of the true body: the full '// &
            'model of each hang, cycles times the period plus noise of '//rshort(sigma)//' s)'
        row = ''
        do k = 1, tab%ncol
            if (k > 1) row = row//','
            row = row//tab%names(k)%s
        end do
        write (u, '(a)') row
        do i = 1, tab%nrow
            associate (r => set%obs(i))
                if (allocated(tc)) then
                    tp = tc(prob%row_case(i))
                else
                    call hang_rig(d%body%mass, d%suspension%g, set%releases(r%release)%hang, &
                                  x, rg, st)
                    if (st%code == 0) call hang_period(rg, accuracy_of(d), r%amplitude, tp, st)
                    if (st%code /= 0) call fail('line '//itoa(r%line)//': '//st%msg)
                end if
                tp = r%cycles*tp + sigma*rng_normal(g)
            end associate
            row = ''
            do k = 1, tab%ncol
                if (k > 1) row = row//','
                if (k == c_per) then
                    row = row//fixed(tp, 9)
                else if (tab%v(i, k) == anint(tab%v(i, k)) .and. abs(tab%v(i, k)) < 1.0e9_dp) then
                    row = row//itoa(nint(tab%v(i, k)))
                else
                    row = row//rshort(tab%v(i, k))
                end if
            end do
            write (u, '(a)') row
        end do
        close (u)
    end subroutine make_hangs
    function real_arg(i) result(x)
        integer, intent(in) :: i
        real(dp) :: x
        character(len=256) :: s
        call get_command_argument(i, s)
        read (s, *, iostat=ios) x
        if (ios /= 0) call fail('argument '//trim(s)//' is not a number')
    end function real_arg
    subroutine usage()
        call fail('usage: make_record record DECK DURATION RATE SIGMA SEED angle|rate OUT'// &
                  ' | make_record periods DECK SIGMA SEED A1 [A2 ...] | make_record trials '// &
                  'DECK OUT SEED SIGMA SCATTER RELEASES TIMINGS CYCLES AMP L1 [L2 ...]'// &
                  ' | make_record hangs DECK SIGMA SEED OUT')
    end subroutine usage
    subroutine fail(msg)
        character(len=*), intent(in) :: msg
        write (error_unit, '(a)') 'make_record: '//msg
        flush (error_unit)
        call c_exit(2_c_int)
    end subroutine fail
end program make_record_main
