!> Extreme cases and robustness (issue 5): the model-validity checks, the decks of
!! input/extreme/ run end to end through the executable, and a fuzz test of hostile decks.
module test_extreme
    use kinds, only: dp, pi
    use status, only: status_t, ERR_MODEL
    use testing, only: tester_t
    use output_io, only: read_kv
    use bifilar_model, only: motion_t
    use simulate, only: model_checks
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

    !> Fuzz test: number of hostile decks, and the seed of the generator.
    integer, parameter :: NFUZZ = 240
    integer, parameter :: FUZZ_SEED = 20261121

contains

    subroutine run_extreme_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call execute_command_line('mkdir -p '//SCRATCH)
        if (t%want('extreme: model checks (slack cable, CD vertical, BC horizontal)')) &
            call test_model_checks(t)
        if (t%want('extreme: decks of input/extreme')) call test_decks(t, exe)
        if (t%want('extreme: every deck of input/ (except charts) in this build')) &
            call test_input_decks(t, exe)
        if (t%want('extreme: fuzzed hostile decks')) call test_fuzz(t, exe)
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
            call execute_command_line('rm -rf '//outdir//' && mkdir -p '//outdir)
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
                call t%check('extreme '//nm//': diagnostic "'//trim(cases(k)%word)//'"', f1 .and. f2)
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
        call execute_command_line('rm -rf '//outdir//' && mkdir -p '//outdir)
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
        call t%check('elastic_slack: .slack intervals ordered, inside the run', ordered .and. inside)
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
    !! build) runs through the executable of this build: exit 0, no NaN or Inf written.
    subroutine test_input_decks(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: list, outdir
        character(len=512) :: line
        integer :: u, ios, ex, n
        list = SCRATCH//'/input_decks.txt'
        outdir = SCRATCH//'/input_out'
        call execute_command_line('grep -L "analyses *= *''[^'']*chart" input/*.nml > '// &
                                  list//'; rm -rf '//outdir//'; mkdir -p '//outdir)
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

    ! ---------------------------------------------------------------------------------------
    !> Hostile decks from a fixed seed: random and extreme values, NaN and Inf as text,
    !! missing groups, truncated files, long strings, random bytes.  Each run (under
    !! `timeout 20`) ends with 0, 2, 3 or 4, a non-zero end says 'bifilar:', and no written
    !! file holds a NaN or Inf.
    subroutine test_fuzz(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer(8) :: state
        integer :: k, ex, nbad_status, nbad_msg, nbad_nan, counts(0:5)
        character(len=:), allocatable :: path, outdir, log
        character(len=80) :: first_bad
        logical :: said
        state = FUZZ_SEED
        nbad_status = 0
        nbad_msg = 0
        nbad_nan = 0
        counts = 0
        first_bad = ''
        outdir = SCRATCH//'/fuzz_out'
        do k = 1, NFUZZ
            path = SCRATCH//'/fz_'//itoa(k)//'.nml'
            log = SCRATCH//'/fz_'//itoa(k)//'.log'
            call write_fuzz_deck(path, k, state)
            call execute_command_line('rm -rf '//outdir//' && mkdir -p '//outdir)
            call execute_command_line('timeout 20 '//exe//' '//path//' --out '//outdir// &
                                      ' > '//log//' 2>&1', exitstat=ex)
            said = .true.
            if (ex >= 0 .and. ex <= 4) then
                counts(ex) = counts(ex) + 1
            else
                counts(5) = counts(5) + 1
            end if
            if (.not. (ex == 0 .or. ex == 2 .or. ex == 3 .or. ex == 4)) then
                nbad_status = nbad_status + 1
                if (len_trim(first_bad) == 0) first_bad = path//' exit '//itoa(ex)
            else if (ex /= 0) then
                said = file_has(log, 'bifilar:')
            end if
            if (ex /= 0 .and. .not. said .and. (ex == 2 .or. ex == 3 .or. ex == 4)) then
                nbad_msg = nbad_msg + 1
                if (len_trim(first_bad) == 0) first_bad = path//' no bifilar: message'
            end if
            if (.not. no_nan(outdir)) then
                nbad_nan = nbad_nan + 1
                if (len_trim(first_bad) == 0) first_bad = path//' NaN in output'
            end if
        end do
        write (*, '(a,i0,a,6(i0,a))') '   fuzz: ', NFUZZ, ' decks; exit 0: ', counts(0), &
            ', 1: ', counts(1), ', 2: ', counts(2), ', 3: ', counts(3), ', 4: ', counts(4), &
            ', other: ', counts(5), ''
        if (len_trim(first_bad) > 0) write (*, '(a)') '   first failing deck: '//trim(first_bad)
        call t%check('fuzz: every exit status is 0, 2, 3 or 4', nbad_status == 0)
        call t%check('fuzz: every failing run says bifilar: ...', nbad_msg == 0)
        call t%check('fuzz: no NaN or Inf in any output', nbad_nan == 0)
        call t%check('fuzz: some decks run, some are refused', counts(0) > 0 .and. counts(2) > 0)
    end subroutine test_fuzz

    !> Deck number k of the fuzz test.
    subroutine write_fuzz_deck(path, k, state)
        character(len=*), intent(in) :: path
        integer, intent(in) :: k
        integer(8), intent(inout) :: state
        character(len=200) :: grp(6)
        character(len=:), allocatable :: text
        character(len=28), parameter :: vars(26) = [character(len=28) :: &
            'scene:title', 'scene:analyses', 'scene:model', 'suspension:b', &
            'suspension:b_prime', 'suspension:l', 'suspension:l_prime', 'suspension:g', &
            'body:mass', 'body:inertia', 'body:r', 'body:lambda', 'body:sway_depth', &
            'body:btilde(1,:)', 'start:mode', 'start:amplitude', 'start:tilt', 'start:theta', &
            'start:theta_dot', 'integration:tau_end', 'integration:dtau_out', &
            'integration:rtol', 'integration:atol', 'integration:error_estimate', &
            'floquet:amplitude', 'floquet:segments']
        character(len=24), parameter :: hostile(24) = [character(len=24) :: 'NaN', 'Inf', &
            '-Inf', '+Infinity', 'nan()', '1e400', '-1e400', '1e-400', '0', '-0.0', &
            '1.7976931348623157e308', '4.9e-324', '-1', '1e300', '1e-300', '2147483648', &
            '''abc''', 'abc', '.true.', '3*', '1,2,3,4,5,6,7,8,9,10', '1d0', '', '(1.0,2.0)']
        character(len=24), parameter :: words(8) = [character(len=24) :: '''simulate''', &
            '''floquet''', '''simulate floquet''', '''work_precision''', '''chart''', &
            '''garbage''', '''angles''', '''raised''']
        integer :: kind, i, n, pos, g, j
        character(len=:), allocatable :: v, var, gname
        grp(1) = '&scene title = ''fuzz'', analyses = ''simulate'' /'
        grp(2) = '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 1.8, g = 1.0 /'
        grp(3) = '&body mass = 1.0, inertia = 0.125, 0.1458333333333333, 0.1458333333333333,'// &
                 ' r = 0.7071067811865476, lambda = 0.7853981633974483, sway_depth = 1.0 /'
        grp(4) = '&start mode = ''raised'', amplitude = 45.0, tilt = 0.0 /'
        grp(5) = '&integration tau_end = 2.0, dtau_out = 0.1, rtol = 1e-8, atol = 1e-10 /'
        grp(6) = '&floquet amplitude = 45.0, segments = 1, rtol = 1e-8 /'
        kind = mod(k, 8)
        text = ''
        select case (kind)
        case (0, 1, 6)
            ! one to three variables set to a hostile, random or long value
            n = 1 + int(3*rnd(state))
            do j = 1, n
                i = 1 + int(size(vars)*rnd(state))
                var = trim(vars(i))
                pos = index(var, ':')
                gname = var(1:pos - 1)
                var = var(pos + 1:)
                select case (kind)
                case (0)
                    v = trim(hostile(1 + int(size(hostile)*rnd(state))))
                    if (var == 'analyses' .or. var == 'mode' .or. var == 'model') &
                        v = trim(words(1 + int(size(words)*rnd(state))))
                case (1)
                    v = random_real(state)
                    if (var == 'analyses' .or. var == 'mode' .or. var == 'model') &
                        v = trim(words(1 + int(size(words)*rnd(state))))
                case default
                    if (rnd(state) < 0.5_dp) then
                        v = ''''//repeat('x', 100 + int(20000*rnd(state)))//''''
                    else
                        v = repeat('9', 50 + int(5000*rnd(state)))
                    end if
                end select
                g = group_index(gname)
                grp(g) = grp(g)(1:len_trim(grp(g)) - 1)//', '//var//' = '//v//' /'
                ! a long value cannot fit grp: write it separately
                if (len(v) > 60) grp(g) = '&'//gname//' '//var//' = '//'@LONG@ /'
                if (len(v) > 60) text = v
            end do
            call write_groups(path, grp, text)
        case (2)
            ! groups missing
            n = 1 + int(3*rnd(state))
            do j = 1, n
                grp(1 + int(6*rnd(state))) = ''
            end do
            call write_groups(path, grp, '')
        case (3)
            ! truncated
            text = assemble(grp)
            n = int(len(text)*rnd(state))
            call write_bytes(path, text(1:n))
        case (4)
            ! random bytes inserted
            text = assemble(grp)
            do j = 1, 1 + int(5*rnd(state))
                pos = 1 + int(len(text)*rnd(state))
                text = text(1:pos - 1)//random_bytes(state, 1 + int(20*rnd(state)))//text(pos:)
            end do
            call write_bytes(path, text)
        case (5)
            ! nothing but random bytes, or an '&' group of them
            if (rnd(state) < 0.5_dp) then
                call write_bytes(path, random_bytes(state, int(3000*rnd(state))))
            else
                call write_bytes(path, '&suspension '//random_bytes(state, 200)//' /'// &
                                 new_line('a')//'&body '//random_bytes(state, 200)//' /')
            end if
        case default
            ! structure: duplicated, unknown or unterminated groups, bad subscripts,
            ! repeat counts, an empty file
            select case (int(7*rnd(state)))
            case (0)
                grp(6) = grp(2)
            case (1)
                grp(6) = '&nonsense x = 1 /'
            case (2)
                grp(2) = grp(2)(1:len_trim(grp(2)) - 1)
            case (3)
                grp(4) = '&start mode = ''angles'', theta(7) = 1.0, theta_dot(0) = 2.0 /'
            case (4)
                grp(3) = '&body btilde(4,1) = 1.0, inertia(-3) = 1 /'
            case (5)
                grp(3) = '&body inertia = 1000000*0.1 /'
            case default
                grp = ''
            end select
            call write_groups(path, grp, '')
        end select
    end subroutine write_fuzz_deck

    integer function group_index(gname)
        character(len=*), intent(in) :: gname
        select case (gname)
        case ('scene')
            group_index = 1
        case ('suspension')
            group_index = 2
        case ('body')
            group_index = 3
        case ('start')
            group_index = 4
        case ('integration')
            group_index = 5
        case default
            group_index = 6
        end select
    end function group_index

    function assemble(grp) result(text)
        character(len=*), intent(in) :: grp(:)
        character(len=:), allocatable :: text
        integer :: i
        text = ''
        do i = 1, size(grp)
            if (len_trim(grp(i)) > 0) text = text//trim(grp(i))//new_line('a')
        end do
    end function assemble

    !> Write the groups; '@LONG@' in a group stands for the long value `long`.
    subroutine write_groups(path, grp, long)
        character(len=*), intent(in) :: path, grp(:), long
        character(len=:), allocatable :: text
        integer :: p
        text = assemble(grp)
        p = index(text, '@LONG@')
        if (p > 0) text = text(1:p - 1)//long//text(p + 6:)
        call write_bytes(path, text)
    end subroutine write_groups

    subroutine write_bytes(path, text)
        character(len=*), intent(in) :: path, text
        integer :: u
        open (newunit=u, file=path, access='stream', form='unformatted', status='replace', &
              action='write')
        write (u) text
        close (u)
    end subroutine write_bytes

    !> Uniform in [0, 1) from a 64-bit linear congruential generator (fixed seed: the same
    !! decks on every machine).
    real(dp) function rnd(state)
        integer(8), intent(inout) :: state
        integer(8), parameter :: a = 6364136223846793005_8, c = 1442695040888963407_8
        state = a*state + c     ! wraps modulo 2**64 (two's complement)
        rnd = real(ishft(state, -11), dp)*2.0_dp**(-53)
    end function rnd

    function random_bytes(state, n) result(s)
        integer(8), intent(inout) :: state
        integer, intent(in) :: n
        character(len=n) :: s
        integer :: i
        do i = 1, n
            s(i:i) = achar(int(256*rnd(state)))
        end do
    end function random_bytes

    !> A real of random sign and magnitude 1e-320 ... 1e320 (as text).
    function random_real(state) result(s)
        integer(8), intent(inout) :: state
        character(len=:), allocatable :: s
        character(len=40) :: buf
        real(dp) :: m
        integer :: e
        m = 1.0_dp + 9.0_dp*rnd(state)
        e = int(640*rnd(state)) - 320
        if (rnd(state) < 0.5_dp) e = int(8*rnd(state)) - 4
        write (buf, '(f0.6,a,i0)') m, 'e', e
        s = trim(buf)
        if (rnd(state) < 0.3_dp) s = '-'//s
    end function random_real

    ! ---------------------------------------------------------------------------------------
    !> True when no data line (not starting '#') of any file in dir holds nan or inf.
    logical function no_nan(dir)
        character(len=*), intent(in) :: dir
        integer :: ex
        call execute_command_line('cat '//dir//'/* 2>/dev/null | grep -v ''^#'' | '// &
            'grep -qiE ''(^|[^a-z])[+-]?(nan|inf)''', exitstat=ex)
        no_nan = ex /= 0
    end function no_nan

    !> True when the text file path contains word.
    logical function file_has(path, word)
        character(len=*), intent(in) :: path, word
        integer :: u, ios
        character(len=4096) :: line
        file_has = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, word) > 0) then
                file_has = .true.
                exit
            end if
        end do
        close (u)
    end function file_has


    function itoa(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function itoa

end module test_extreme
