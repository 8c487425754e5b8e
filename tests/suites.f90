!> The test suites in one table: a row per suite with its name, one line on what it checks
!! and the procedure that runs it (run_tests runs them in the table's order); and suite
!! `runner`, the checks of the runner itself, which needs the table.
!!
!! Adding a suite: write tests/test_X.f90, module test_X with `run_X_tests(t, exe)` (the
!! interface suite_run), and add its row to suite_table.  The Makefile finds the file and
!! its dependencies by itself.
module suites
    use testing, only: tester_t, exists, file_has, count_lines, line_starts, run, fresh_dir
    use text, only: itoa
    use test_lsoda, only: run_lsoda_tests
    use test_deck, only: run_deck_tests
    use test_model, only: run_model_tests
    use test_floquet, only: run_floquet_tests
    use test_extreme, only: run_extreme_tests
    use test_fuzz, only: run_fuzz_tests
    use test_fuzz_resume, only: run_fuzz_resume_tests
    use test_fuzz_tables, only: run_fuzz_table_tests
    use test_work_precision, only: run_work_precision_tests
    use test_elastic, only: run_elastic_tests
    use test_elastic_jac, only: run_elastic_jac_tests
    use test_radau, only: run_radau_tests
    use test_elastic_radau, only: run_elastic_radau_tests
    use test_robust, only: run_robust_tests
    use test_fast_format, only: run_fast_format_tests
    use test_columns, only: run_columns_tests
    use test_period, only: run_period_tests
    use test_design, only: run_design_tests
    use test_sweep, only: run_sweep_tests
    use test_identify, only: run_identify_tests
    use test_graph, only: run_graph_tests
    use test_stats, only: run_stats_tests
    use test_estimator, only: run_estimator_tests
    use test_measure, only: run_measure_tests
    use test_tare, only: run_tare_tests
    use test_sensitivities, only: run_sensitivities_tests
    use test_rates, only: run_rates_tests
    use test_split, only: run_split_tests
    use test_point, only: run_point_tests
    use test_tensor, only: run_tensor_tests
    use test_refusals, only: run_refusals_tests
    use test_tensor_lab, only: run_tensor_lab_tests
    use test_platform, only: run_platform_tests
    use test_platform_tensor, only: run_platform_tensor_tests
    use test_certificate, only: run_certificate_tests
    use test_calibrate, only: run_calibrate_tests
    use test_selfcheck, only: run_selfcheck_tests
    implicit none
    private

    public :: suite_table, suite_names

    !> Longest suite name and description.
    integer, parameter, public :: NAME_LEN = 16, ABOUT_LEN = 80

    abstract interface
        !> Run the parts of a suite that t selects (tester_t%want); exe: the path of the
        !! bifilar executable under test (every suite is given it, used or not).
        subroutine suite_run(t, exe)
            import :: tester_t
            type(tester_t), intent(inout) :: t
            character(len=*), intent(in) :: exe
        end subroutine suite_run
    end interface

    !> A suite: a short unique name (one word), what it checks, the procedure that runs it.
    type, public :: suite_t
        character(len=NAME_LEN) :: name = ''
        character(len=ABOUT_LEN) :: about = ''
        procedure(suite_run), pointer, nopass :: run => null()
    end type suite_t

    character(len=*), parameter :: SCRATCH = 'build/test_runner'

contains

    !> The suites, in the order they run.
    function suite_table() result(table)
        type(suite_t), allocatable :: table(:)
        table = [ &
            suite_t('lsoda', 'LSODA: exact solutions, the standard problems, tolerances, '// &
                    'failures, options', run_lsoda_tests), &
            suite_t('deck', 'the deck reader (every value, every bad input), the echo, '// &
                    'atomic output files', run_deck_tests), &
            suite_t('model', 'kinematics, equations of motion, tensions, the paper''s '// &
                    'scenes and claims', run_model_tests), &
            suite_t('floquet', 'Floquet analysis of pure torsion: Jacobian, multipliers, '// &
                    'refusals, the chart', run_floquet_tests), &
            suite_t('extreme', 'model-validity checks, the decks of input/extreme/ and '// &
                    'input/, slack and snap', run_extreme_tests), &
            suite_t('fuzz', 'about 2000 hostile decks, records, hangs through the executable', &
                    run_fuzz_tests), &
            suite_t('fuzz_resume', 'checkpoints damaged, forged and not files; signals at '// &
                    'every stage; --out limits', run_fuzz_resume_tests), &
            suite_t('fuzz_tables', 'records, periods, hangs, checkpoints mutated; '// &
                    'read in process', run_fuzz_table_tests), &
            suite_t('work_precision', 'work-precision curves, their reference, RK4''s '// &
                    'order, the error estimate', run_work_precision_tests), &
            suite_t('elastic', 'elastic cables: conversions, energy, convergence to the '// &
                    'paper''s model, slack', run_elastic_tests), &
            suite_t('elastic_jac', 'the elastic model''s analytic Jacobian against '// &
                    'central differences', run_elastic_jac_tests), &
            suite_t('radau', 'Radau IIA: coefficients, a cubic, standard problems, '// &
                    'failures; shared checks', run_radau_tests), &
            suite_t('elastic_radau', 'elastic cables in generalized coordinates by '// &
                    'Radau IIA, against CVODE', run_elastic_radau_tests), &
            suite_t('robust', 'daily use through the executable: several decks, --out, '// &
                    'a full disk, the report', run_robust_tests), &
            suite_t('fast_format', 'ESw.dE3 and Fw.d text against the run-time library; '// &
                    'numbers in messages', run_fast_format_tests), &
            suite_t('columns', 'deck group &output: a subset of the .dat columns, bad '// &
                    'names', run_columns_tests), &
            suite_t('period', 'random streams; I1 from measured periods, its budget and '// &
                    'Monte Carlo', run_period_tests), &
            suite_t('design', 'rig design: the recommendation, band edges, the classical '// &
                    'limit, threads', run_design_tests), &
            suite_t('sweep', 'sweeps over threads and MPI ranks, checkpoints, killed and '// &
                    'resumed', run_sweep_tests), &
            suite_t('identify', 'damping, periods of asymmetric rigs, least squares, '// &
                    'record fits, examples', run_identify_tests), &
            suite_t('measure', 'measurement as done: instrument files, releases pooled, '// &
                    'traps, tare, trifilar', run_measure_tests), &
            suite_t('calibrate', 'rig calibration with a reference body: a calibrated rig '// &
                    'measures a second body', run_calibrate_tests), &
            suite_t('tare', 'a tare from its own output: shared inputs correlated, its '// &
                    'dof kept, refusals', run_tare_tests), &
            suite_t('sensitivities', 'forward sensitivities: exact, against differences of '// &
                    'runs, fits, monodromies', run_sensitivities_tests), &
            suite_t('rates', 'records of three body rates: model vs pose, I2 I3 cg_depth, '// &
                    'refusals', &
                    run_rates_tests), &
            suite_t('split', 'a record of several releases cut at its holds, the segments '// &
                    'pooled as a table', run_split_tests), &
            suite_t('point', 'a tracked point (video): model vs pose, sensitivities, '// &
                    'sway, scale, refusals', run_point_tests), &
            suite_t('stats', 'Student''s t, chi-square tails, Welch-Satterthwaite, weighted '// &
                    'means', run_stats_tests), &
            suite_t('estimator', 'least squares: known answers, rank deficiency, Huber, '// &
                    'chi-square, roundoff', run_estimator_tests), &
            suite_t('tensor', 'the inertia tensor from several hangs: exact fit, projection, '// &
                    'u, plan, refusals', run_tensor_tests), &
            suite_t('tensor_lab', 'the tensor''s fixtures, the mass centre from the hangs, '// &
                    'the plan', run_tensor_lab_tests), &
            suite_t('platform', 'a body on n cables: the paper''s model, torsion, modes, '// &
                    'limits, test mass', run_platform_tests), &
            suite_t('platform_tensor', 'the tensor on a trifilar: its model, fits, the '// &
                    'fixture, refusals', run_platform_tensor_tests), &
            suite_t('refusals', 'measurement mistakes: wrong numbers, wrong causes; '// &
                    'each right or refused', run_refusals_tests), &
            suite_t('certificate', 'the certificate page: SVG figures, escaping, balanced '// &
                    'elements, its fields', run_certificate_tests), &
            suite_t('selfcheck', 'records and tensors check themselves; amplitude '// &
                    'scale; budgets vs whole fits', run_selfcheck_tests), &
            suite_t('graph', 'the module graph (layers, analyses apart, at most 8 floors); '// &
                    'the status table', run_graph_tests), &
            suite_t('runner', 'this runner: --list, --help, a filter that selects '// &
                    'nothing', run_runner_tests)]
    end function suite_table

    !> The names of the suites, in the table's order, separated by sep.
    function suite_names(table, sep) result(s)
        type(suite_t), intent(in) :: table(:)
        character(len=*), intent(in) :: sep
        character(len=:), allocatable :: s
        integer :: k
        s = ''
        do k = 1, size(table)
            if (k > 1) s = s//sep
            s = s//trim(table(k)%name)
        end do
    end function suite_names

    ! ---------------------------------------------------------------------------------------
    !> Suite runner: the table (names unique, one word; descriptions whole), and the runner
    !! run again from here (its path is argument 0): --list, --help, an unknown option, and
    !! a filter that selects nothing.
    subroutine run_runner_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('runner: the table, --list, --help and a filter that selects nothing')) &
            call test_runner(t, exe)
    end subroutine run_runner_tests

    !> The table's rows, then this runner run as a child: --list, --help, an unknown option,
    !! and filter nosuchsuite (exit status, stdout, the stderr line).
    subroutine test_runner(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(suite_t), allocatable :: table(:)
        character(len=4096) :: arg0
        character(len=:), allocatable :: self, d, nm
        integer :: ex, k, j
        logical :: ok
        allocate (table, source=suite_table())
        ok = size(table) > 0
        do k = 1, size(table)
            nm = trim(table(k)%name)
            ok = ok .and. len(nm) > 0 .and. len(nm) < NAME_LEN .and. index(nm, ' ') == 0 .and. &
                len_trim(table(k)%about) > 0 .and. len_trim(table(k)%about) < ABOUT_LEN .and. &
                associated(table(k)%run)
            do j = 1, k - 1
                ok = ok .and. table(j)%name /= table(k)%name
            end do
        end do
        call t%check('runner: suite names unique, one word, descriptions whole, procedures '// &
                     'set', ok)
        call get_command_argument(0, arg0)
        self = trim(arg0)
        call t%check('runner: its own path (argument 0) '//self//' found', exists(self))
        if (.not. exists(self)) return
        d = SCRATCH
        call fresh_dir(d)

        ex = run(self//' --list', d)
        call t%check('runner: --list exits 0 (got '//itoa(ex)//')', ex == 0)
        ok = count_lines(d//'/stdout') == size(table)
        do k = 1, size(table)
            ok = all([ok, line_starts(d//'/stdout', k, trim(table(k)%name)//' '), &
                     file_has(d//'/stdout', ' '//trim(table(k)%about))])
        end do
        call t%check('runner: --list lists every suite of the table, one per line', ok)

        ex = run(self//' --help', d)
        call t%check('runner: --help exits 0 with the usage on stdout', all([ex == 0, &
                     line_starts(d//'/stdout', 1, 'usage: '), count_lines(d//'/stderr') == 0]))
        ex = run(self//' '//exe//' --frobnicate', d)
        call t%check('runner: an unknown option exits non-zero (got '//itoa(ex)//')', &
                     all([ex /= 0, file_has(d//'/stderr', '--frobnicate')]))

        ex = run(self//' '//exe//' nosuchsuite', d)
        call t%check('runner: a filter that selects nothing exits non-zero (got '// &
                     itoa(ex)//')', ex /= 0)
        call t%check('runner: ... with "0 passed, 0 failed" on stdout', all([ &
                     count_lines(d//'/stdout') == 1, &
                     line_starts(d//'/stdout', 1, '0 passed, 0 failed')]))
        call t%check('runner: ... and one stderr line naming the filter and every suite', &
                     all([count_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', '''nosuchsuite'''), &
                     file_has(d//'/stderr', suite_names(table, ', '))]))
    end subroutine test_runner

end module suites
