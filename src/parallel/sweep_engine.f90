!> Sweeps of independent points over ranks and threads, with checkpoints.
!!
!! A sweep is n points; point i is computed from i alone by a task (`sweep_task_t`, its
!! `compute(i, values, stat)` gives a fixed number of reals), so points may be computed in
!! any order, by any thread of any rank, and the values come back in index order: every
!! file made from them is the same byte for byte whatever the ranks, threads or
!! interruptions.  Used by the stability chart (module stability), the three sweeps of
!! the rig design (module design) and identify's Monte Carlo (module monte_carlo).
!!
!! Work sharing (dynamic, because points differ a lot in cost): rank 0 keeps the list of
!! points to do and hands them out in chunks, on request, to the other ranks (module
!! parallel: MPI in bin/bifilar_mpi, one rank in bin/bifilar).  A chunk is a share of what
!! is left, ceil(left * t / (2 T)) points for a rank of t threads out of T in all, at least
!! t and at most CHUNK_MAX_PER_THREAD * t, so chunks shrink towards the end.  A rank asks
!! for its next chunk while it still has t points of the last one to do, so its threads do
!! not wait for the answer.  Inside a rank, OpenMP threads take the points one at a time
!! (OMP_NUM_THREADS is honoured).  Rank 0 computes points too (with up to RANK0_COMPUTES_MAX
!! ranks; environment BIFILAR_RANK0_COMPUTES = yes or no decides otherwise) and answers
!! requests between its points.  Only rank 0 writes files and prints.
!!
!! Checkpoints: rank 0 writes the completed points to OUTDIR/NAME.ANALYSIS.partial (module
!! checkpoint: the file, its fingerprint of the run) at most every `checkpoint_seconds` (and
!! at most 5 % of the time: the interval is at least 20 times the last write).  The
!! fingerprint's CRC-64s (module crc64), of the deck file (and of the sweep's payload, when
!! the task needs more than the deck) and of the executable, are also how the other ranks
!! check that they read the same deck and run the same executable as rank 0.  With
!! `resume`, a checkpoint whose fingerprint matches supplies its points and the rest are
!! computed; any other checkpoint is ignored (and replaced by the next one).  Every point
!! taken from a checkpoint is checked as if it had been computed (its record's checksum,
!! and the task's `accepts`: finite, in its range); one that fails is computed again, and
!! the report counts it.  A checkpoint that cannot be written does not end the sweep: the
!! report carries one warning and the sweep goes on without checkpoints.  A sweep stopped
!! by a signal (SIGINT, SIGTERM, SIGHUP; under mpirun SIGTERM) is handled by module signals
!! for the whole run: the sweep only names itself as the stage, and its checkpoint once
!! written, in the one line the handler prints.
!!
!! Failures: a point whose compute returns an error ends the sweep with that error (the
!! other ranks are told to stop; the sweep returns once every rank has finished its running
!! points), and its checkpoint is removed.  A rank that cannot set up the sweep (cannot read
!! the deck, reads another deck or runs another executable) ends it too; the checkpoint of
!! an earlier run is then left as it was.
!!
!! Messages (payloads of reals, first element the sweep's number): rank 0 -> others JOB (a
!! sweep begins: its size, fingerprint, analysis, deck and payload), WORK (a chunk of
!! indices; none means nothing is left), STOP (drop your points: the sweep failed), BYE
!! (your part of the sweep is over), QUIT (the program ends); others -> rank 0 RESULTS
!! (completed points, and a request for more), ERROR (a point or the setup failed), LEAVE
!! (last results: done).
!!
!! State: no module variables.  A sweep's state is its own (`engine_t`, local to sweep_run
!! and sweep_serve).  One count outlives the sweeps (one of the three places of module state
!! src/README.md allows): rank 0's number of sweeps begun, saved in `sweep_count`, which
!! numbers each sweep's messages so that rank 0 rejects a message of any other sweep than
!! the running one (a late message of a sweep that failed arrives during the next); it
!! belongs to the process, as the ranks do, so no caller could keep it.  The signal
!! handler's state is in module signals.
module sweep_engine
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use finite, only: finite_bits
    use status, only: status_t, set_error, STATUS_OK, ERR_IO, ERR_DECK
    use text, only: itoa
    use output_io, only: remove_file
    use progress, only: progress_t, pace_t
    use parallel, only: par_start, par_stop, par_rank, par_ranks, par_post, par_poll, &
        par_recv, par_library, PAR_ANY
    use crc64, only: deck_crc, executable_crc, crc_parts, crc_join, hex16
    use checkpoint, only: checkpoint_path, checkpoint_write, checkpoint_read
    use signals, only: signals_stage, signals_stage_now, signals_mpi, signals_kept
    use unused_arg, only: unused
    !$ use omp_lib, only: omp_get_max_threads
    implicit none
    private

    !> The points of a sweep: extend it with what the points need and a `compute`.
    type, abstract, public :: sweep_task_t
    contains
        procedure(sweep_compute_i), deferred :: compute
        !> Whether values could be point i's (for values taken from a checkpoint); the
        !! default: every value finite.  A task whose points have ranges or sentinels says
        !! so by overriding it.
        procedure :: accepts => sweep_accepts
    end type sweep_task_t

    abstract interface
        !> The values of point i (1 <= i <= points) from i alone.  Runs on many threads at
        !! once: must not change shared state.  A non-OK stat ends the whole sweep (a point
        !! that merely has no answer should return a sentinel value instead).
        subroutine sweep_compute_i(self, i, values, stat)
            import :: sweep_task_t, dp, status_t
            class(sweep_task_t), intent(in) :: self     !! the sweep's data
            integer, intent(in) :: i                    !! point index
            real(dp), intent(out) :: values(:)          !! its values
            type(status_t), intent(out) :: stat         !! non-OK: fatal for the sweep
        end subroutine sweep_compute_i
    end interface

    !> How a sweep treats its checkpoint (from the command line: --resume, --checkpoint).
    type, public :: sweep_options_t
        logical :: resume = .false.                 !! continue from a matching checkpoint
        real(dp) :: checkpoint_seconds = 5.0_dp     !! least time between two checkpoints
    end type sweep_options_t

    !> What a sweep did, for the summary line.
    type, public :: sweep_report_t
        integer :: ranks = 1                        !! ranks of the run
        integer :: threads = 1                      !! OpenMP threads of all ranks
        integer :: resumed = 0                      !! points taken from the checkpoint
        !> points of the checkpoint computed again: a record damaged or missing, or values
        !! the task does not accept
        integer :: rejected = 0
        integer :: checkpoints = 0                  !! checkpoints written
        character(len=:), allocatable :: note       !! why a checkpoint was not resumed ('')
        !> why the sweep went on without checkpoints ('' when it did not)
        character(len=:), allocatable :: warning
        real(dp) :: wall_seconds = 0.0_dp           !! elapsed time of the sweep
        integer :: requests = 0                     !! requests for work rank 0 answered
        real(dp) :: serve_seconds = 0.0_dp          !! rank 0's time taking messages
    end type sweep_report_t

    !> A sweep as the other ranks learn of it (JOB): they build the task from the analysis,
    !! the deck and the payload (module driver, serve_sweeps).
    type, public :: sweep_job_t
        integer :: id = 0                           !! the sweep's number
        integer :: npoints = 0, nvalues = 0
        integer(int64) :: deck_crc = 0, exe_crc = 0 !! fingerprint parts
        character(len=:), allocatable :: analysis   !! e.g. 'chart'
        character(len=:), allocatable :: deck_path  !! the deck as rank 0 was given it
        !> the deck's text as rank 0 read it ('' when each rank reads the file deck_path)
        character(len=:), allocatable :: deck_text
        real(dp), allocatable :: payload(:)         !! what else the task needs (may be empty)
    end type sweep_job_t

    public :: sweep_run, sweep_start, sweep_finish, sweep_is_master, sweep_next_job
    public :: sweep_resume_points
    public :: sweep_serve, sweep_library
    public :: checkpoint_path                       ! (of module checkpoint)

    !> A chunk holds at most this many points per thread of the rank that gets it.
    integer, parameter :: CHUNK_MAX_PER_THREAD = 64
    !> Rank 0 computes points when the run has at most this many ranks; beyond, it only
    !! hands out work (answering quickly matters more than one rank's points).
    integer, parameter :: RANK0_COMPUTES_MAX = 16
    !> Waiting for a message: sleeps growing from NAP_MIN to NAP_MAX microseconds.
    integer, parameter :: NAP_MIN = 50, NAP_MAX = 2000
    !> The checkpoint interval is at least this multiple of the last write's duration.
    real(dp), parameter :: CHECKPOINT_COST_FACTOR = 20.0_dp

    ! message kinds
    integer, parameter :: TAG_JOB = 1, TAG_QUIT = 2, TAG_WORK = 3, TAG_STOP = 4, TAG_BYE = 5, &
        TAG_RESULTS = 6, TAG_ERROR = 7, TAG_LEAVE = 8
    ! what a thread does after a step
    integer, parameter :: ACT_COMPUTE = 1, ACT_WAIT = 2, ACT_EXIT = 3

    !> The state of one rank in one sweep (shared by its threads; changed only inside the
    !! critical section `sweep_step`).
    type :: engine_t
        integer :: id = 0                           !! the sweep's number
        integer :: n = 0, nv = 0                    !! points, values per point
        logical :: master = .true.                  !! rank 0
        integer :: nranks = 1, nt = 1               !! ranks, this rank's threads
        ! this rank's points to do: queue(qhead:qtail)
        integer, allocatable :: queue(:)
        integer :: qhead = 1, qtail = 0
        ! rank 0
        real(dp), allocatable :: values(:, :)       !! (nv, n)
        logical, allocatable :: done(:)
        integer, allocatable :: todo(:)             !! points not done, ascending
        integer :: next = 1                         !! next of todo to hand out
        integer :: ndone = 0
        integer, allocatable :: threads(:)          !! threads of each rank (0: not known)
        logical, allocatable :: left(:)             !! rank has left the sweep
        logical :: computes = .true.                !! rank 0 computes points
        logical :: failed = .false.
        type(status_t) :: err                       !! the first failure
        logical :: point_failed = .false.           !! the failure was a point's
        type(progress_t) :: pr
        !> the one 'bifilar: note:' line of a sweep still running after note_after() s
        type(pace_t) :: pc
        character(len=:), allocatable :: ckpt       !! checkpoint path ('' none)
        character(len=:), allocatable :: analysis
        real(dp), allocatable :: payload(:)         !! sent with JOB
        integer(int64) :: deck_crc = 0, exe_crc = 0
        character(len=:), allocatable :: ckpt_warning   !! a checkpoint could not be written
        real(dp) :: interval = 5.0_dp               !! least seconds between checkpoints
        real(dp) :: asked_interval = 5.0_dp
        integer(int64) :: last_ckpt = 0             !! clock of the last checkpoint
        integer :: ndone_ckpt = 0                   !! points in the last checkpoint
        integer :: nckpt = 0                        !! checkpoints written
        integer :: requests = 0                     !! requests answered
        integer(int64) :: serve_clock = 0           !! clock ticks spent taking messages
        ! the other ranks
        logical :: awaiting = .false.               !! a request is on its way
        logical :: exhausted = .false.              !! rank 0 has nothing left
        logical :: stopped = .false.                !! the sweep failed
        real(dp), allocatable :: out(:)             !! results to send: (i, values) ...
        integer :: nout = 0                         !! points in out
    end type engine_t

    interface
        integer(c_int) function c_usleep(usec) bind(C, name='usleep')
            import :: c_int
            integer(c_int), value :: usec
        end function c_usleep
    end interface

contains

    ! ================================================================ the program's ranks

    !> Begin the run's message passing (MPI_Init in bin/bifilar_mpi; nothing in bin/bifilar).
    subroutine sweep_start(stat)
        type(status_t), intent(out) :: stat         !! a failure of the MPI library
        call par_start(stat)
        if (stat%code == STATUS_OK .and. par_rank() == 0) call signals_mpi(par_ranks())
    end subroutine sweep_start

    !> True on rank 0, the rank that reads the command line, runs the decks and writes.
    logical function sweep_is_master()
        sweep_is_master = par_rank() == 0
    end function sweep_is_master

    !> End the run: rank 0 tells the other ranks to finish (QUIT), then every rank ends its
    !! message passing (MPI_Finalize).
    subroutine sweep_finish()
        integer :: r
        if (par_rank() == 0) then
            do r = 1, par_ranks() - 1
                call par_post(r, TAG_QUIT, [real(sweep_count(0), dp)])
            end do
        end if
        call par_stop()
    end subroutine sweep_finish

    !> The message-passing library of this build, for --version.
    function sweep_library() result(s)
        character(len=:), allocatable :: s
        s = par_library()
    end function sweep_library

    !> Rank 0's count of the sweeps it has begun, after adding `add` (1 when one begins, 0 to
    !! ask): the only state the module keeps from sweep to sweep (see the module's notes).
    integer function sweep_count(add)
        integer, intent(in) :: add                  !! sweeps begun now
        integer, save :: n = 0
        n = n + add
        sweep_count = n
    end function sweep_count

    ! ================================================================ rank 0

    !> Compute every point of a sweep over all ranks (called on rank 0; the other ranks
    !! take part through sweep_serve): values(:, i) = point i.  With `ckpt` (a path, or ''
    !! for none) the sweep is checkpointed and, with options%resume, continued from a
    !! checkpoint of the same deck, analysis and executable.
    subroutine sweep_run(task, analysis, deck_path, ckpt, label, npoints, nvalues, values, &
                         stat, options, report, payload, deck_text)
        class(sweep_task_t), intent(in) :: task     !! the points
        character(len=*), intent(in) :: analysis    !! e.g. 'chart'
        character(len=*), intent(in) :: deck_path   !! the deck file (as given)
        character(len=*), intent(in) :: ckpt        !! checkpoint path ('' none)
        character(len=*), intent(in) :: label       !! progress label, e.g. 'box: chart'
        integer, intent(in) :: npoints, nvalues
        real(dp), allocatable, intent(out) :: values(:, :)  !! (nvalues, npoints)
        type(status_t), intent(out) :: stat         !! the first failure
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(out), optional :: report
        !> What else the other ranks need to build the task beyond the deck (the task's own
        !! encoding; part of the fingerprint)
        real(dp), intent(in), optional :: payload(:)
        !> The deck as read (deck_t%text): the fingerprint's, and sent to the other ranks,
        !! which then need no file of the deck; without it the deck file at deck_path
        character(len=*), intent(in), optional :: deck_text
        type(engine_t) :: e
        type(sweep_options_t) :: opt
        character(len=:), allocatable :: text
        type(sweep_report_t) :: rep
        integer :: r, k, nbad
        integer(int64) :: c0, c1, rate
        logical :: had_ckpt
        character(len=16) :: env
        character(len=:), allocatable :: stage0

        stat%code = STATUS_OK
        if (present(options)) opt = options
        call system_clock(c0, rate)
        e%id = sweep_count(1)
        e%n = npoints
        e%nv = nvalues
        e%master = .true.
        e%nranks = par_ranks()
        e%nt = 1
        !$ e%nt = omp_get_max_threads()
        e%computes = e%nranks <= RANK0_COMPUTES_MAX
        call get_environment_variable('BIFILAR_RANK0_COMPUTES', env)
        if (trim(env) == 'yes') e%computes = .true.
        if (trim(env) == 'no' .and. e%nranks > 1) e%computes = .false.
        e%analysis = analysis
        e%ckpt = ckpt
        e%asked_interval = max(0.0_dp, opt%checkpoint_seconds)
        e%interval = e%asked_interval
        allocate (e%values(nvalues, npoints), e%done(npoints), e%threads(0:e%nranks - 1), &
                  e%left(0:e%nranks - 1), e%queue(0))
        e%values = 0.0_dp
        e%done = .false.
        e%threads = 0
        e%threads(0) = e%nt
        e%left = .false.
        e%left(0) = .true.
        rep%ranks = e%nranks
        rep%note = ''
        rep%warning = ''
        e%ckpt_warning = ''

        if (present(payload)) then
            e%payload = payload
        else
            allocate (e%payload(0))
        end if
        if (len(ckpt) > 0 .or. e%nranks > 1) then      ! (a fingerprint is needed)
            call deck_crc(deck_path, e%payload, e%deck_crc, stat, deck_text)
            if (stat%code /= STATUS_OK) then
                stat%msg = analysis//': cannot read the deck for the sweep''s fingerprint: '// &
                    stat%msg
                return
            end if
            e%exe_crc = executable_crc()
        end if

        had_ckpt = .false.
        if (len(ckpt) > 0 .and. opt%resume) then
            call sweep_resume_points(task, ckpt, analysis, e%deck_crc, e%exe_crc, e%values, &
                                     e%done, e%ndone, nbad, rep%note)
            rep%resumed = e%ndone
            rep%rejected = nbad
            had_ckpt = e%ndone > 0
        end if
        e%ndone_ckpt = e%ndone
        e%todo = pack([(k, k=1, npoints)], .not. e%done)
        e%next = 1

        ! tell the other ranks
        text = ''
        if (present(deck_text)) text = deck_text
        do r = 1, e%nranks - 1
            call par_post(r, TAG_JOB, job_message(e, deck_path, text))
        end do

        call e%pr%start(label, npoints)
        if (e%ndone > 0) call e%pr%tick(e%ndone)
        if (e%master) call e%pc%start('bifilar: note: '//deck_path//': '//analysis, &
                                      real(e%ndone, dp), real(npoints, dp), 'points', every=1)
        call system_clock(e%last_ckpt)
        ! the signal line names this sweep (and its checkpoint once one is kept: module
        ! checkpoint); a checkpoint resumed is kept already
        stage0 = signals_stage_now()
        call signals_stage(analysis, sweep=len(ckpt) > 0)
        if (had_ckpt) call signals_kept(ckpt)
        call run_threads(e, task)
        call master_finish(e)
        call e%pr%finish()
        if (.not. e%failed .and. len(e%ckpt) > 0 .and. (e%nckpt > 0 .or. had_ckpt) .and. &
            e%ndone > e%ndone_ckpt) call write_checkpoint(e)
        call signals_stage(stage0)
        rep%warning = e%ckpt_warning

        rep%threads = sum(e%threads)
        rep%checkpoints = e%nckpt
        rep%requests = e%requests
        rep%serve_seconds = real(e%serve_clock, dp)/real(rate, dp)
        call system_clock(c1)
        rep%wall_seconds = real(c1 - c0, dp)/real(rate, dp)
        if (present(report)) report = rep
        if (e%failed) then
            stat = e%err
            if (e%point_failed .and. len(ckpt) > 0) call remove_file(ckpt)
            return
        end if
        call move_alloc(e%values, values)
    end subroutine sweep_run

    !> The points of a sweep's checkpoint that --resume takes (module checkpoint: the
    !! fingerprint, each record's checksum), each then checked as if computed
    !! (task%accepts): those that fail are not done and counted in nbad with the damaged
    !! records; note says why no point was taken ('' when the header was).
    subroutine sweep_resume_points(task, ckpt, analysis, deck_crc, exe_crc, values, done, &
                                   ndone, nbad, note)
        class(sweep_task_t), intent(in) :: task     !! the points
        character(len=*), intent(in) :: ckpt        !! the checkpoint's path
        character(len=*), intent(in) :: analysis    !! e.g. 'chart'
        integer(int64), intent(in) :: deck_crc, exe_crc     !! the fingerprint
        real(dp), intent(inout) :: values(:, :)     !! (values, points)
        logical, intent(inout) :: done(:)           !! the points taken
        integer, intent(out) :: ndone               !! their number
        integer, intent(out) :: nbad                !! points damaged or refused
        character(len=:), allocatable, intent(out) :: note
        integer :: k
        call checkpoint_read(ckpt, analysis, deck_crc, exe_crc, values, done, ndone, nbad, note)
        do k = 1, size(done)
            if (.not. done(k)) cycle
            if (task%accepts(k, values(:, k))) cycle
            done(k) = .false.
            values(:, k) = 0.0_dp
            ndone = ndone - 1
            nbad = nbad + 1
        end do
    end subroutine sweep_resume_points

    !> The JOB message: id, points, values, the fingerprint, the analysis and the deck.
    function job_message(e, deck_path, deck_text) result(m)
        type(engine_t), intent(in) :: e
        character(len=*), intent(in) :: deck_path
        character(len=*), intent(in) :: deck_text   !! '' when the ranks read the file
        real(dp), allocatable :: m(:)
        m = [real(e%id, dp), real(e%n, dp), real(e%nv, dp), crc_parts(e%deck_crc), &
             crc_parts(e%exe_crc), real(len(e%analysis), dp), real(len(deck_path), dp), &
             real(size(e%payload), dp), real(len(deck_text), dp), chars_to_reals(e%analysis), &
             chars_to_reals(deck_path), e%payload, chars_to_reals(deck_text)]
    end function job_message

    !> Rank 0 after its threads are done: answer the other ranks until every one has left,
    !! checkpointing as due.
    subroutine master_finish(e)
        type(engine_t), intent(inout) :: e
        integer :: nap
        logical :: got
        nap = NAP_MIN
        do while (.not. all(e%left))
            call master_serve(e, got)
            call maybe_checkpoint(e)
            if (got) then
                nap = NAP_MIN
            else
                call nap_for(nap)
            end if
        end do
    end subroutine master_finish

    !> Rank 0: take every message that has arrived and act on it; got: there was one.
    subroutine master_serve(e, got)
        type(engine_t), intent(inout) :: e
        logical, intent(out) :: got
        integer :: src, tag, n, code, i, lm
        integer(int64) :: c0, c1
        logical :: found
        real(dp), allocatable :: m(:)
        got = .false.
        c0 = 0_int64                    ! set on the first message (gcc -flto cannot see it)
        do
            call par_poll(PAR_ANY, src, tag, n, found)
            if (.not. found) exit
            if (.not. got) call system_clock(c0)
            got = .true.
            allocate (m(max(n, 1)))
            call par_recv(src, tag, m(1:n))
            if (n < 1) then
                call fail(e, ERR_IO, e%analysis//': internal error: an empty message from '// &
                          'rank '//itoa(src), .false.)
            else if (nint(m(1)) /= e%id) then
                call fail(e, ERR_IO, e%analysis//': internal error: rank '//itoa(src)// &
                          ' sent a message of sweep '//itoa(nint(m(1)))//' during sweep '// &
                          itoa(e%id), .false.)
            else
                select case (tag)
                case (TAG_RESULTS)          ! id, want, threads, count, (i, values) ...
                    e%threads(src) = nint(m(3))
                    call store_results(e, m(5:n), nint(m(4)))
                    if (nint(m(2)) == 1) call answer(e, src)
                case (TAG_LEAVE)            ! id, threads, count, (i, values) ...
                    e%threads(src) = nint(m(2))
                    call store_results(e, m(4:n), nint(m(3)))
                    e%left(src) = .true.
                    call par_post(src, TAG_BYE, [real(e%id, dp)])
                case (TAG_ERROR)            ! id, point (0: setup), code, length, text
                    i = nint(m(2))
                    code = nint(m(3))
                    lm = nint(m(4))
                    if (i == 0) then
                        call fail(e, code, e%analysis//': rank '//itoa(src)//': '// &
                                  reals_to_chars(m(5:4 + lm)), .false.)
                    else
                        call fail(e, code, reals_to_chars(m(5:4 + lm)), .true.)
                    end if
                case default
                    call fail(e, ERR_IO, e%analysis//': internal error: message kind '// &
                              itoa(tag)//' from rank '//itoa(src), .false.)
                end select
            end if
            deallocate (m)
        end do
        if (got) then
            call system_clock(c1)
            e%serve_clock = e%serve_clock + (c1 - c0)
        end if
    end subroutine master_serve

    !> Rank 0: store `count` results (i, values) ... of buf.
    subroutine store_results(e, buf, count)
        type(engine_t), intent(inout) :: e
        real(dp), intent(in) :: buf(:)
        integer, intent(in) :: count
        integer :: k, i, p
        p = 0
        do k = 1, count
            i = nint(buf(p + 1))
            if (i >= 1 .and. i <= e%n) then
                if (.not. e%done(i)) then
                    e%values(:, i) = buf(p + 2:p + 1 + e%nv)
                    e%done(i) = .true.
                    e%ndone = e%ndone + 1
                end if
            end if
            p = p + 1 + e%nv
        end do
        if (count > 0) call e%pr%tick(count)
        if (count > 0) call e%pc%check(real(e%ndone, dp))
    end subroutine store_results

    !> Rank 0: answer rank src's request: a chunk (WORK; empty when nothing is left) or STOP.
    subroutine answer(e, src)
        type(engine_t), intent(inout) :: e
        integer, intent(in) :: src
        integer, allocatable :: c(:)
        if (e%failed) then
            call par_post(src, TAG_STOP, [real(e%id, dp)])
            return
        end if
        e%requests = e%requests + 1
        call take_chunk(e, max(1, e%threads(src)), c)
        call par_post(src, TAG_WORK, [real(e%id, dp), real(size(c), dp), real(c, dp)])
    end subroutine answer

    !> Rank 0: the next chunk of points for a rank of t threads (see the module's notes).
    subroutine take_chunk(e, t, c)
        type(engine_t), intent(inout) :: e
        integer, intent(in) :: t                    !! the rank's threads
        integer, allocatable, intent(out) :: c(:)
        integer :: left, tall, m, r
        left = size(e%todo) - e%next + 1
        if (left <= 0) then
            allocate (c(0))
            return
        end if
        tall = 0
        do r = 0, e%nranks - 1
            if (e%threads(r) > 0) then
                tall = tall + e%threads(r)
            else if (r > 0 .or. e%computes) then
                tall = tall + t                     ! not known yet: like this one
            end if
        end do
        if (.not. e%computes) tall = max(1, tall - e%threads(0))
        m = int((int(left, int64)*t + 2*tall - 1)/(2*tall))
        m = max(m, t)
        m = min(m, CHUNK_MAX_PER_THREAD*t, left)
        c = e%todo(e%next:e%next + m - 1)
        e%next = e%next + m
    end subroutine take_chunk

    !> Record the sweep's first failure and stop everything: the other ranks get STOP, this
    !! rank's queue is dropped.  point: the failure is a point's (the checkpoint goes).
    subroutine fail(e, code, msg, point)
        type(engine_t), intent(inout) :: e
        integer, intent(in) :: code
        character(len=*), intent(in) :: msg
        logical, intent(in) :: point
        integer :: r
        if (e%failed) return
        e%failed = .true.
        e%point_failed = point
        call set_error(e%err, code, msg)
        e%qhead = e%qtail + 1
        e%next = size(e%todo) + 1
        do r = 1, e%nranks - 1
            if (.not. e%left(r)) call par_post(r, TAG_STOP, [real(e%id, dp)])
        end do
    end subroutine fail

    ! ================================================================ the other ranks

    !> Another rank: wait for the next sweep (JOB) or the end of the program (QUIT).
    subroutine sweep_next_job(job, quit)
        type(sweep_job_t), intent(out) :: job       !! the sweep, when quit is false
        logical, intent(out) :: quit                !! the program ends
        integer :: tag, la, lp, lq, lt
        real(dp), allocatable :: m(:)
        quit = .false.
        do
            call wait_message(tag, m)
            if (tag == TAG_QUIT) then
                quit = .true.
                return
            end if
            if (tag == TAG_JOB .and. size(m) >= 11) exit
        end do                                      ! (a stray message of an ended sweep)
        job%id = nint(m(1))
        job%npoints = nint(m(2))
        job%nvalues = nint(m(3))
        job%deck_crc = crc_join(m(4:5))
        job%exe_crc = crc_join(m(6:7))
        la = nint(m(8))
        lp = nint(m(9))
        lq = nint(m(10))
        lt = nint(m(11))
        job%analysis = reals_to_chars(m(12:11 + la))
        job%deck_path = reals_to_chars(m(12 + la:11 + la + lp))
        job%payload = m(12 + la + lp:11 + la + lp + lq)
        job%deck_text = reals_to_chars(m(12 + la + lp + lq:11 + la + lp + lq + lt))
    end subroutine sweep_next_job

    !> Another rank: take part in the sweep `job` with `task` (built from the job by the
    !! caller); setup: the caller's failure to build it (then task is not used and the
    !! sweep fails with that message).  Returns when rank 0 has let this rank go.
    subroutine sweep_serve(job, setup, task)
        type(sweep_job_t), intent(in) :: job
        type(status_t), intent(in) :: setup         !! building the task failed when not OK
        class(sweep_task_t), intent(in), optional :: task
        type(engine_t) :: e
        type(status_t) :: st
        e%id = job%id
        e%n = job%npoints
        e%nv = job%nvalues
        e%master = .false.
        e%nranks = par_ranks()
        e%nt = 1
        !$ e%nt = omp_get_max_threads()
        e%analysis = job%analysis
        allocate (e%queue(0), e%out(0))
        st = setup
        if (st%code == STATUS_OK) then
            if (.not. present(task)) call set_error(st, ERR_DECK, 'no task for analysis '// &
                job%analysis)
        end if
        if (st%code == STATUS_OK) call check_fingerprint(job, st)
        if (st%code /= STATUS_OK) then
            call post_error(e, 0, st)
            e%stopped = .true.
        else
            call run_threads(e, task)
        end if
        call worker_leave(e)
    end subroutine sweep_serve

    !> This rank's deck and executable against rank 0's.
    subroutine check_fingerprint(job, stat)
        type(sweep_job_t), intent(in) :: job
        type(status_t), intent(out) :: stat
        integer(int64) :: crc
        if (len(job%deck_text) > 0) then
            call deck_crc(job%deck_path, job%payload, crc, stat, job%deck_text)
        else
            call deck_crc(job%deck_path, job%payload, crc, stat)
        end if
        if (stat%code /= STATUS_OK) return
        if (crc /= job%deck_crc) then
            call set_error(stat, ERR_DECK, 'reads another deck at '//job%deck_path// &
                           ' than rank 0 (CRC-64 '//hex16(crc)//', rank 0 '// &
                           hex16(job%deck_crc)//'): every rank must see the same file')
            return
        end if
        crc = executable_crc()
        if (crc /= job%exe_crc) then
            call set_error(stat, ERR_DECK, 'runs another executable than rank 0 (CRC-64 '// &
                           hex16(crc)//', rank 0 '//hex16(job%exe_crc)// &
                           '): every rank must run the same bin/bifilar_mpi')
        end if
    end subroutine check_fingerprint

    !> Another rank: send an ERROR (point i, 0 for the setup).
    subroutine post_error(e, i, st)
        type(engine_t), intent(in) :: e
        integer, intent(in) :: i
        type(status_t), intent(in) :: st
        character(len=:), allocatable :: msg
        msg = message_of(st)
        call par_post(0, TAG_ERROR, [real(e%id, dp), real(i, dp), real(st%code, dp), &
                      real(len(msg), dp), chars_to_reals(msg)])
    end subroutine post_error

    !> Another rank, its threads done: send the last results (LEAVE) and wait for BYE,
    !! dropping whatever else rank 0 sent meanwhile (a chunk, STOP).
    subroutine worker_leave(e)
        type(engine_t), intent(inout) :: e
        integer :: tag
        real(dp), allocatable :: m(:)
        call par_post(0, TAG_LEAVE, [real(e%id, dp), real(e%nt, dp), real(e%nout, dp), &
                      e%out(1:e%nout*(1 + e%nv))])
        e%nout = 0
        do
            call wait_message(tag, m)
            if (tag == TAG_BYE) exit
        end do
    end subroutine worker_leave

    !> Another rank: wait (napping) for the next message from rank 0 and receive it.
    subroutine wait_message(tag, m)
        integer, intent(out) :: tag                 !! its kind
        real(dp), allocatable, intent(out) :: m(:)  !! its payload
        integer :: src, n, nap
        logical :: found
        nap = NAP_MIN
        do
            call par_poll(0, src, tag, n, found)
            if (found) exit
            call nap_for(nap)
        end do
        allocate (m(n))
        call par_recv(src, tag, m)
    end subroutine wait_message

    !> Another rank: take the messages from rank 0 (chunks, STOP).
    subroutine worker_listen(e)
        type(engine_t), intent(inout) :: e
        integer :: src, tag, n, c
        logical :: found
        real(dp), allocatable :: m(:)
        do
            call par_poll(0, src, tag, n, found)
            if (.not. found) exit
            allocate (m(max(n, 1)))
            call par_recv(src, tag, m(1:n))
            select case (tag)
            case (TAG_WORK)
                e%awaiting = .false.
                c = nint(m(2))
                if (c == 0) e%exhausted = .true.
                if (.not. e%stopped .and. c > 0) call enqueue(e, nint(m(3:2 + c)))
            case (TAG_STOP)
                e%stopped = .true.
                e%qhead = e%qtail + 1
            end select
            deallocate (m)
        end do
    end subroutine worker_listen

    ! ================================================================ every rank

    !> The rank's threads: each takes a point, computes it, hands it in, until no point is
    !! left for it.  All bookkeeping (and every message) inside one critical section.
    subroutine run_threads(e, task)
        type(engine_t), intent(inout) :: e
        class(sweep_task_t), intent(in) :: task
        integer :: i, action, nap
        real(dp), allocatable :: vals(:)
        type(status_t) :: st
        !$omp parallel num_threads(e%nt) default(shared) private(i, action, nap, vals, st)
        allocate (vals(e%nv))
        vals = 0.0_dp
        i = 0
        nap = NAP_MIN
        do
            !$omp critical (sweep_step)
            call step(e, i, vals, st, action)
            !$omp end critical (sweep_step)
            if (action == ACT_EXIT) exit
            if (action == ACT_WAIT) then
                call nap_for(nap)
                cycle
            end if
            nap = NAP_MIN
            call task%compute(i, vals, st)
        end do
        deallocate (vals)
        !$omp end parallel
    end subroutine run_threads

    !> One step of a thread (inside the critical section): hand in point i (when i > 0)
    !! with its values and status, take messages, ask for or hand out work, and pick the
    !! thread's next point (i, action ACT_COMPUTE), or ACT_WAIT, or ACT_EXIT.
    subroutine step(e, i, vals, st, action)
        type(engine_t), intent(inout) :: e
        integer, intent(inout) :: i
        real(dp), intent(in) :: vals(:)
        type(status_t), intent(in) :: st
        integer, intent(out) :: action
        logical :: got
        integer, allocatable :: c(:)
        if (e%master) then
            if (i > 0) then
                if (st%code /= STATUS_OK) then
                    call fail(e, st%code, message_of(st), .true.)
                else if (.not. e%done(i)) then
                    e%values(:, i) = vals
                    e%done(i) = .true.
                    e%ndone = e%ndone + 1
                    call e%pr%tick()
                    call e%pc%check(real(e%ndone, dp))
                end if
            end if
            call master_serve(e, got)
            call maybe_checkpoint(e)
            if (e%computes .and. .not. e%failed .and. e%qtail - e%qhead + 1 <= e%nt) then
                call take_chunk(e, e%nt, c)
                if (size(c) > 0) call enqueue(e, c)
            end if
        else
            if (i > 0) then
                if (st%code /= STATUS_OK) then
                    if (.not. e%stopped) call post_error(e, i, st)
                    e%stopped = .true.
                    e%qhead = e%qtail + 1
                else
                    call add_result(e, i, vals)
                end if
            end if
            call worker_listen(e)
            if (.not. (e%awaiting .or. e%exhausted .or. e%stopped) .and. &
                e%qtail - e%qhead + 1 <= e%nt) then
                call par_post(0, TAG_RESULTS, [real(e%id, dp), 1.0_dp, real(e%nt, dp), &
                              real(e%nout, dp), e%out(1:e%nout*(1 + e%nv))])
                e%nout = 0
                e%awaiting = .true.
            end if
        end if
        i = 0
        if (e%qhead <= e%qtail) then
            i = e%queue(e%qhead)
            e%qhead = e%qhead + 1
            action = ACT_COMPUTE
        else if (e%master .or. e%exhausted .or. e%stopped) then
            action = ACT_EXIT
        else
            action = ACT_WAIT
        end if
    end subroutine step

    !> The message of a status ('(no message)' when it has none).
    function message_of(st) result(m)
        type(status_t), intent(in) :: st
        character(len=:), allocatable :: m
        m = '(no message)'
        if (allocated(st%msg)) m = st%msg
    end function message_of

    !> The default of sweep_task_t%accepts: values could be a point's when every one is
    !! finite.
    logical function sweep_accepts(self, i, values) result(ok)
        class(sweep_task_t), intent(in) :: self     !! the sweep's data
        integer, intent(in) :: i                    !! point index
        real(dp), intent(in) :: values(:)           !! its values, as read from a checkpoint
        call unused(self)                           ! the default needs none of its data
        ok = all(finite_bits(values)) .and. i >= 1
    end function sweep_accepts

    !> Append points to the rank's queue.
    subroutine enqueue(e, c)
        type(engine_t), intent(inout) :: e
        integer, intent(in) :: c(:)
        integer, allocatable :: q(:)
        integer :: m
        m = e%qtail - e%qhead + 1
        allocate (q(m + size(c)))
        q(1:m) = e%queue(e%qhead:e%qtail)
        q(m + 1:) = c
        call move_alloc(q, e%queue)
        e%qhead = 1
        e%qtail = m + size(c)
    end subroutine enqueue

    !> Another rank: keep point i's values to send with the next request.
    subroutine add_result(e, i, vals)
        type(engine_t), intent(inout) :: e
        integer, intent(in) :: i
        real(dp), intent(in) :: vals(:)
        real(dp), allocatable :: grown(:)
        integer :: need
        need = (e%nout + 1)*(1 + e%nv)
        if (need > size(e%out)) then
            allocate (grown(max(need, 2*size(e%out))))
            grown(1:e%nout*(1 + e%nv)) = e%out(1:e%nout*(1 + e%nv))
            call move_alloc(grown, e%out)
        end if
        e%out(need - e%nv:need - e%nv) = real(i, dp)
        e%out(need - e%nv + 1:need) = vals
        e%nout = e%nout + 1
    end subroutine add_result

    !> Sleep nap microseconds, then double nap (up to NAP_MAX).
    subroutine nap_for(nap)
        integer, intent(inout) :: nap
        integer(c_int) :: rc
        rc = c_usleep(int(nap, c_int))
        nap = min(2*nap, NAP_MAX)
    end subroutine nap_for

    ! ================================================================ checkpoints

    !> Rank 0: write a checkpoint when one is due (its interval passed and points were added).
    subroutine maybe_checkpoint(e)
        type(engine_t), intent(inout) :: e
        integer(int64) :: c, rate
        if (len(e%ckpt) == 0 .or. e%failed .or. e%ndone == e%ndone_ckpt) return
        call system_clock(c, rate)
        if (real(c - e%last_ckpt, dp) < e%interval*real(rate, dp)) return
        call write_checkpoint(e)
    end subroutine maybe_checkpoint

    !> Rank 0: write the checkpoint now (module checkpoint).  One that cannot be written
    !! (a full disk, a folder in its place) does not end the sweep, whose own file may well
    !! fit: the sweep goes on without checkpoints, and its report says why (one warning).
    !! A checkpoint written before stays (its points are still right).
    subroutine write_checkpoint(e)
        type(engine_t), intent(inout) :: e
        integer(int64) :: c0, c1, rate
        type(status_t) :: st
        call system_clock(c0, rate)
        call checkpoint_write(e%ckpt, e%analysis, e%deck_crc, e%exe_crc, e%values, e%done, st)
        if (st%code /= STATUS_OK) then
            e%ckpt_warning = message_of(st)//': going on without checkpoints (--resume '// &
                'cannot continue this run from here)'
            e%ckpt = ''
            return
        end if
        e%nckpt = e%nckpt + 1
        e%ndone_ckpt = e%ndone
        call system_clock(c1)
        e%last_ckpt = c1
        e%interval = max(e%asked_interval, CHECKPOINT_COST_FACTOR*real(c1 - c0, dp)/real(rate, dp))
    end subroutine write_checkpoint

    ! ================================================================ message contents

    !> Characters as reals (their codes), for a message.
    pure function chars_to_reals(s) result(r)
        character(len=*), intent(in) :: s
        real(dp) :: r(len(s))
        integer :: k
        do k = 1, len(s)
            r(k) = real(ichar(s(k:k)), dp)
        end do
    end function chars_to_reals

    !> The inverse of chars_to_reals.
    pure function reals_to_chars(r) result(s)
        real(dp), intent(in) :: r(:)
        character(len=size(r)) :: s
        integer :: k
        do k = 1, size(r)
            s(k:k) = char(max(0, min(255, nint(r(k)))))
        end do
    end function reals_to_chars

end module sweep_engine
