!> Extreme cases and robustness: the model-validity checks, the decks of
!! input/extreme/ and every deck of input/ but the charts run end to end through the
!! executable, the elastic model through slack and snap.  The fuzz test of hostile decks is
!! suite fuzz (test_fuzz).
module test_extreme
    use kinds, only: dp, pi
    use status, only: status_t, ERR_MODEL, ERR_NUMERIC
    use testing, only: tester_t, file_has, no_nan, scratch_dir, fresh_dir
    use output_io, only: read_kv
    use bifilar_model, only: motion_t
    use kane_run, only: model_checks
    use run_loop, only: check_row_budget, MAX_STEPS_PER_ROW
    use text, only: fixed, itoa
    implicit none
    private

    public :: run_extreme_tests

    character(len=*), parameter :: SCRATCH = 'build/test_extreme'

    !> One deck of input/extreme/ and what must happen to it.
    type :: case_t
        character(len=32) :: name = ''
        integer :: exit_status = 0          !! expected exit status
        real(dp) :: rtol = 1.0e-10_dp       !! the deck's rtol
        real(dp) :: multiple = 10.0_dp      !! finishing decks: energy, constraint <= multiple*rtol
        character(len=40) :: word = ''      !! failing decks: the diagnostic contains this
    end type case_t

contains

    subroutine run_extreme_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCRATCH)
        if (t%want('extreme: model checks (slack cable, CD vertical, BC horizontal)')) &
            call test_model_checks(t)
        if (t%want('extreme: decks of input/extreme')) call test_decks(t, exe)
        if (t%want('extreme: every deck of input/ (except charts) in this build')) &
            call test_input_decks(t, exe)
        if (t%want('extreme: elastic model through slack and snap')) &
            call test_elastic_slack(t, exe)
    end subroutine run_extreme_tests

    ! ---------------------------------------------------------------------------------------
    !> model_checks: ERR_MODEL with what, when and what to change; nothing on a valid motion.
    subroutine test_model_checks(t)
        type(tester_t), intent(inout) :: t
        type(motion_t) :: mo
        type(status_t) :: st
        mo%t_bc = 0.5_dp
        mo%t_ad = 0.5_dp
        mo%th = [0.1_dp, 0.2_dp, 0.3_dp, 0.4_dp, 0.5_dp]
        call model_checks(mo, 1.5_dp, st)
        call t%check('model checks: a valid motion passes', st%code == 0)
        mo%t_ad = -1.0e-3_dp
        call model_checks(mo, 1.5_dp, st)
        call t%check('model checks: slack cable is ERR_MODEL', st%code == ERR_MODEL)
        if (st%code /= 0) call t%check('model checks: slack message (what, tau, remedy)', &
            index(st%msg, 'slack') > 0 .and. index(st%msg, 'tau = 1.5') > 0 .and. &
            index(st%msg, 'lower the amplitude') > 0)
        mo%t_ad = 0.5_dp
        mo%th(5) = 0.5_dp*pi - 1.0e-5_dp
        call model_checks(mo, 2.0_dp, st)
        call t%check('model checks: CD vertical is ERR_MODEL', st%code == ERR_MODEL)
        if (st%code /= 0) call t%check('model checks: CD vertical message', &
            index(st%msg, 'vertical') > 0 .and. index(st%msg, 'tau = 2.0') > 0 .and. &
            index(st%msg, 'singular') > 0)
        mo%th(5) = 0.5_dp
        mo%th(2) = 0.5_dp*pi - 1.0e-3_dp
        call model_checks(mo, 3.0_dp, st)
        call t%check('model checks: BC horizontal is ERR_MODEL', st%code == ERR_MODEL)
        if (st%code /= 0) call t%check('model checks: BC horizontal message', &
            index(st%msg, 'horizontal') > 0 .and. index(st%msg, 'tau = 3.0') > 0)
        ! the step budget's message at a huge tau (a record of times 1e116 s: a run-time
        ! error 'End of record' before, found by the fuzz test)
        st%code = 0
        call check_row_budget(MAX_STEPS_PER_ROW, 3.0e116_dp, 2.0e110_dp, 'remedy', st)
        call t%check('model checks: step budget at tau = 3E+116 is ERR_NUMERIC', &
                     st%code == ERR_NUMERIC)
        if (st%code /= 0) call t%check('model checks: step budget message at tau = 3E+116', &
            index(st%msg, 'tau = 3.000000E+116 (last step 2.000E+110): remedy') > 0)
        call t%check('model checks: tau in messages, 42.758454 and -1.000000E+09', &
            fixed(42.758454_dp, 6) == '42.758454' .and. fixed(-1.0e9_dp, 6) == '-1.000000E+09')
    end subroutine test_model_checks

    ! ---------------------------------------------------------------------------------------
    !> Every deck of input/extreme/ through the executable: the expected exit status; for a
    !! finishing deck energy and constraint errors within a stated multiple of rtol; for a
    !! stopping deck a diagnostic naming what happened; never a NaN or Inf in a file.
    subroutine test_decks(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(case_t) :: cases(16)
        integer :: k, ex
        character(len=:), allocatable :: outdir, log, nm
        real(dp) :: de, dc
        logical :: f1, f2, there
        cases(1) = case_t('torsion_120', 0, 1.0e-10_dp, 10.0_dp, '')
        cases(2) = case_t('torsion_170', 0, 1.0e-10_dp, 10.0_dp, '')
        cases(3) = case_t('short_cables', 4, 1.0e-10_dp, 0.0_dp, 'cable goes slack at tau = ')
        cases(4) = case_t('long_cables', 0, 1.0e-10_dp, 10.0_dp, '')
        cases(5) = case_t('unequal_cables', 4, 1.0e-10_dp, 0.0_dp, 'cable goes slack at tau = ')
        cases(6) = case_t('flat_body', 0, 1.0e-10_dp, 10.0_dp, '')
        cases(7) = case_t('slender_body', 4, 1.0e-10_dp, 0.0_dp, 'cable goes slack at tau = 0.0')
        cases(8) = case_t('centre_on_cd', 0, 1.0e-10_dp, 10.0_dp, '')
        cases(9) = case_t('tipping', 4, 1.0e-10_dp, 0.0_dp, 'cable goes slack at tau = 32.')
        cases(10) = case_t('torsion_1000_periods', 0, 1.0e-10_dp, 100.0_dp, '')
        cases(11) = case_t('long_run', 0, 1.0e-10_dp, 100.0_dp, '')
        cases(12) = case_t('fast_start_slack', 4, 1.0e-10_dp, 0.0_dp, 'cable goes slack at tau = ')
        ! the slack falls between rows 0 and 2; the tau is the one a fine output grid finds
        cases(13) = case_t('slack_between_rows', 4, 1.0e-10_dp, 0.0_dp, &
                           'cable goes slack at tau = 0.7320')
        cases(14) = case_t('rtol_1e-14', 3, 1.0e-14_dp, 0.0_dp, '&integration rtol')
        cases(15) = case_t('rtol_3e-14', 0, 3.0e-14_dp, 10.0_dp, '')
        ! elastic cables stiffer than the tolerance resolves: stop at once, say which rtol
        cases(16) = case_t('elastic_chatter', 3, 1.0e-4_dp, 0.0_dp, 'lower rtol to about 1/(2 k)')
        do k = 1, size(cases)
            nm = trim(cases(k)%name)
            outdir = SCRATCH//'/'//nm
            log = SCRATCH//'/'//nm//'.log'
            call fresh_dir(outdir)
            call execute_command_line(exe//' input/extreme/'//nm//'.nml --out '//outdir// &
                                      ' > '//log//' 2>&1', exitstat=ex)
            call t%check('extreme '//nm//': exit status '//itoa(cases(k)%exit_status)// &
                         ' (got '//itoa(ex)//')', ex == cases(k)%exit_status)
            call t%check('extreme '//nm//': no NaN or Inf in any file', no_nan(outdir))
            if (cases(k)%exit_status == 0) then
                call read_kv(outdir//'/'//nm//'.summary', 'max_abs_energy_error', de, f1)
                call read_kv(outdir//'/'//nm//'.summary', 'max_abs_constraint_residual', &
                                   dc, f2)
                call t%check('extreme '//nm//': summary written', f1 .and. f2)
                if (f1 .and. f2) then
                    call t%check('extreme '//nm//': energy error <= '// &
                        itoa(nint(cases(k)%multiple))//' rtol', &
                        de <= cases(k)%multiple*cases(k)%rtol)
                    call t%check('extreme '//nm//': constraint error <= '// &
                        itoa(nint(cases(k)%multiple))//' rtol', &
                        dc <= cases(k)%multiple*cases(k)%rtol)
                end if
            else
                f1 = file_has(log, 'bifilar: error')
                f2 = file_has(log, trim(cases(k)%word))
                call t%check('extreme '//nm//': diagnostic "'//trim(cases(k)%word)//'"', &
                             f1 .and. f2)
                inquire (file=outdir//'/'//nm//'.dat', exist=there)
                call t%check('extreme '//nm//': no .dat left behind', .not. there)
            end if
        end do
    end subroutine test_decks

    ! ---------------------------------------------------------------------------------------
    !> input/extreme/elastic_slack.nml: the elastic model through slack and snap: exit 0, no
    !! NaN, the summary's slack keys present and > 0 for both cables.
    subroutine test_elastic_slack(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: outdir, sumpath
        character(len=*), parameter :: keys(4) = [character(len=20) :: 'slack_time_BC', &
            'slack_time_AD', 'slack_intervals_BC', 'slack_intervals_AD']
        real(dp) :: v
        logical :: found
        integer :: ex, k
        outdir = SCRATCH//'/elastic_slack'
        sumpath = outdir//'/elastic_slack.summary'
        call fresh_dir(outdir)
        call execute_command_line(exe//' input/extreme/elastic_slack.nml --out '//outdir// &
                                  ' > '//outdir//'.log 2>&1', exitstat=ex)
        call t%check('elastic_slack: exit 0 (got '//itoa(ex)//')', ex == 0)
        call t%check('elastic_slack: no NaN or Inf in any file', no_nan(outdir))
        do k = 1, size(keys)
            call read_kv(sumpath, trim(keys(k)), v, found)
            call t%check('elastic_slack: summary '//trim(keys(k))//' > 0', found .and. v > 0.0_dp)
        end do
        call read_kv(sumpath, 'min_tension', v, found)
        call t%check('elastic_slack: min_tension 0 (slack reported, not an error)', &
                     found .and. v == 0.0_dp)
        call check_slack_list(t, outdir//'/elastic_slack.slack', sumpath)
    end subroutine test_elastic_slack

    !> The .slack list of an elastic run agrees with its summary: one row per slack interval
    !! (slack_intervals_BC, _AD), durations summing to slack_time_BC, _AD, intervals in
    !! order and inside the run, cable_switches = 2 rows - open ones - those slack from
    !! tau = 0.
    subroutine check_slack_list(t, path, sumpath)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: path, sumpath
        real(dp) :: t0, t1, dur, tsum(2), v, tend, tprev
        integer :: u, ios, cab, op, n(2), nopen, nstart
        logical :: found, ordered, inside, ok
        character(len=256) :: line
        tsum = 0
        n = 0
        nopen = 0
        nstart = 0
        tprev = -1
        ordered = .true.
        inside = .true.
        call read_kv(sumpath, 'tau_end', tend, found)
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        ok = ios == 0 .and. found
        call t%check('elastic_slack: '//path//' written', ok)
        if (.not. ok) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#') cycle
            read (line, *, iostat=ios) cab, t0, t1, dur, op
            if (ios /= 0 .or. cab < 1 .or. cab > 2) then
                ok = .false.
                exit
            end if
            n(cab) = n(cab) + 1
            tsum(cab) = tsum(cab) + dur
            nopen = nopen + op
            if (t0 == 0.0_dp) nstart = nstart + 1   ! slack from the start: no switch opened it
            ordered = ordered .and. t0 >= tprev .and. t1 >= t0 .and. abs(t1 - t0 - dur) < 1.0e-12_dp
            inside = inside .and. t0 >= 0.0_dp .and. t1 <= tend*(1 + 1.0e-14_dp)
            tprev = t0
        end do
        close (u)
        call t%check('elastic_slack: .slack rows parse', ok)
        call t%check('elastic_slack: .slack intervals ordered, inside the run', &
                     ordered .and. inside)
        call read_kv(sumpath, 'slack_intervals_BC', v, found)
        ok = found .and. nint(v) == n(1)
        call read_kv(sumpath, 'slack_intervals_AD', v, found)
        ok = ok .and. found .and. nint(v) == n(2)
        call t%check('elastic_slack: one .slack row per slack interval of the summary', ok)
        call read_kv(sumpath, 'slack_time_BC', v, found)
        ok = found .and. abs(v - tsum(1)) <= 1.0e-9_dp*tend
        call read_kv(sumpath, 'slack_time_AD', v, found)
        ok = ok .and. found .and. abs(v - tsum(2)) <= 1.0e-9_dp*tend
        call t%check('elastic_slack: .slack durations sum to the summary''s slack times', ok)
        call read_kv(sumpath, 'cable_switches', v, found)
        call t%check('elastic_slack: cable_switches = 2 intervals - open ones - those '// &
                     'slack from the start', found .and. nint(v) == 2*sum(n) - nopen - nstart)
    end subroutine check_slack_list

    ! ---------------------------------------------------------------------------------------
    !> Every deck of input/ that asks for no chart (a chart takes a minute in the checking
    !! build) runs through the executable of this build: exit 0, no NaN or Inf written.  The
    !! decks run from a copy of input/ (their tables and records beside them) with every
    !! Monte Carlo cut to 20 samples: the full samples are the example suites' and make
    !! run's, and 2000 of them take a minute in the checking build.
    subroutine test_input_decks(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: list, outdir, copy
        character(len=512) :: line
        integer :: u, ios, ex, n
        list = SCRATCH//'/input_decks.txt'
        outdir = SCRATCH//'/input_out'
        copy = SCRATCH//'/input_copy'
        call execute_command_line('rm -rf '//copy//' && mkdir -p '//copy//' && '// &
            'for f in input/*; do [ -f "$f" ] && cp "$f" '//copy//'/; done; '// &
            'sed -i ''s/monte_carlo *= *[1-9][0-9]*/monte_carlo = 20/'' '//copy//'/*.nml')
        call execute_command_line('grep -L "analyses *= *''[^'']*chart" '//copy// &
                                  '/*.nml > '//list//'; rm -rf '//outdir//'; mkdir -p '//outdir)
        n = 0
        open (newunit=u, file=list, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (len_trim(line) == 0) cycle
            n = n + 1
            call execute_command_line(exe//' '//trim(line)//' --out '//outdir// &
                                      ' > /dev/null 2>&1', exitstat=ex)
            call t%check('input deck '//trim(line)//': exit 0', ex == 0)
        end do
        close (u)
        call t%check('input decks: at least the eight paper and work-precision decks', n >= 8)
        call t%check('input decks: no NaN or Inf in any file', no_nan(outdir))
    end subroutine test_input_decks

end module test_extreme
