!> SIGINT, SIGTERM and SIGHUP for the whole run: at any moment, in a sweep or not (reading a
!! deck, integrating, fitting, writing), the program removes every temporary file of the
!! run (the registered NAME.*.tmp.PID.N: staged output files and a checkpoint being
!! written), keeps the sweeps' checkpoints (NAME.*.partial), writes one line naming the
!! deck, the stage and the signal to standard error and exits with status 128 + the signal
!! (130 SIGINT, 143 SIGTERM, 129 SIGHUP).  Only SIGKILL can leave a temporary file.
!!
!! How: the handler is installed once (`signals_install`, rank 0 of the program) and does
!! the cleaning itself, with async-signal-safe calls only (unlink(2), write(2),
!! nanosleep(2), _exit(2)) on state prepared beforehand, since a handler is given nothing
!! but the signal's number:
!!
!! - the temporary files: a table of fixed slots (`signals_track` fills a slot before the
!!   file is created, `signals_untrack` frees it once the file is renamed or removed), so
!!   the handler never sees a half-written path or a reallocated array;
!! - the line: composed in advance whenever its parts change (`signals_deck`,
!!   `signals_stage`, `signals_kept`, `signals_mpi`) into the buffer not in use, then
!!   switched to, and written in one write(2), whole or absent;
!! - a deck's files renamed into place (`signals_defer` ... `signals_release`): a signal
!!   then only notes itself, and is acted on when released, so a deck's set of files is
!!   never renamed in part;
!! - once the last deck has printed its line (`signals_ignore`), signals are ignored: the
!!   run is complete.
!!
!! A handler may run on any thread.  It first marks the process as ending; a thread that
!! creates a temporary file after that (`signals_created`) removes it itself and waits for
!! the end, so no file created concurrently with the handler is left behind.
!!
!! Under mpirun: mpirun passes an interrupt (its own SIGINT, SIGTERM or SIGHUP) on to every
!! rank as SIGTERM, and sends SIGTERM when a rank dies; it then waits
!! odls_base_sigkill_timeout (1 s) for the ranks to end, cut short when one ends, before it
!! sends SIGKILL, and it forwards a rank's output only while it still reads it.  So
!! (`signals_mpi`) rank 0 waits LINGER_RANK0 after writing its line before it exits (mpirun
!! reads the line meanwhile), and the other ranks (`signals_worker`) wait LINGER_WORKER
!! before they end quietly, so that their ends do not cut mpirun's wait short before rank 0
!! has spoken (doc/parallel.md).
!!
!! Module state: this is the one module of the program with state (src/README.md); all of
!! it is here because the handler can find nothing else.
module signals
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_funptr, c_funloc, c_null_char, &
        c_size_t, c_long
    implicit none
    private

    public :: signals_install, signals_worker, signals_mpi, signals_deck, signals_stage, &
        signals_stage_now, signals_kept, signals_track, signals_untrack, signals_created, &
        signals_defer, signals_release, signals_ignore

    !> The signals handled: SIGINT, SIGTERM, SIGHUP, and their names.
    integer(c_int), parameter :: HANDLED(3) = [2_c_int, 15_c_int, 1_c_int]
    character(len=7), parameter :: NAMES(3) = ['SIGINT ', 'SIGTERM', 'SIGHUP ']
    !> Capacity of each part of the line (characters; longer parts are cut), of a path, and
    !! the number of temporary files tracked at once.
    integer, parameter :: PART_CAP = 12288, PATH_CAP = 4097, NSLOTS = 128
    !> Waits under mpirun before exiting (nanoseconds): rank 0 after its line, the others.
    integer(c_long), parameter :: LINGER_RANK0 = 300000000_c_long, &
        LINGER_WORKER = 600000000_c_long
    !> What the handler does: nothing installed, rank 0's cleaning and line, another rank's
    !! quiet end.
    integer, parameter :: MODE_NONE = 0, MODE_MAIN = 1, MODE_WORKER = 2

    ! ---- what the handler reads (set beforehand; volatile: changed while it may run)
    integer, volatile, save :: sig_mode = MODE_NONE
    !> The line in two buffers: the part before the signal's number and the part after its
    !! name (newline included); the handler uses buffer sig_active.
    character(kind=c_char), volatile, save :: sig_pre(PART_CAP, 2)
    character(kind=c_char), volatile, save :: sig_post(PART_CAP, 2)
    integer, volatile, save :: sig_pre_len(2) = 0, sig_post_len(2) = 0
    integer, volatile, save :: sig_active = 1
    !> Temporary files: null-terminated paths, and whether each slot is in use.
    character(kind=c_char), volatile, save :: slot_path(PATH_CAP, NSLOTS)
    integer, volatile, save :: slot_used(NSLOTS) = 0
    !> A deferred signal (signals_defer): noted in sig_pending, acted on by signals_release.
    integer, volatile, save :: sig_defer = 0, sig_pending = 0
    !> Signals ignored (the run is complete); the process is ending (a handler has begun).
    integer, volatile, save :: sig_ignore = 0, sig_ending = 0
    !> Linger before exiting (an MPI run of several ranks).
    integer, volatile, save :: sig_linger = 0
    !> The handler's own buffer for the line.
    character(kind=c_char), save :: sig_out(2*PART_CAP + 32)

    ! ---- what the line is made of (normal state, read only by `compose`)
    character(len=:), allocatable, save :: line_deck, line_stage, line_kept, line_why
    logical, save :: line_sweep = .false.

    interface
        type(c_funptr) function c_signal(sig, handler) bind(C, name='signal')
            import :: c_int, c_funptr
            integer(c_int), value :: sig
            type(c_funptr), value :: handler
        end function c_signal
        integer(c_size_t) function c_write(fd, buf, n) bind(C, name='write')
            import :: c_int, c_char, c_size_t
            integer(c_int), value :: fd
            character(kind=c_char), dimension(*), intent(in) :: buf
            integer(c_size_t), value :: n
        end function c_write
        integer(c_int) function c_unlink(path) bind(C, name='unlink')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: path
        end function c_unlink
        integer(c_int) function c_nanosleep(req, rem) bind(C, name='nanosleep')
            import :: c_int, c_long
            integer(c_long), intent(in) :: req(2)       !! struct timespec: seconds, ns
            integer(c_long), intent(out) :: rem(2)
        end function c_nanosleep
        subroutine c_exit_now(status) bind(C, name='_exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit_now
    end interface

contains

    ! ================================================================ installing

    !> Rank 0 (and the serial program): from now on SIGINT, SIGTERM and SIGHUP remove the
    !! run's temporary files, write the line and exit with 128 + the signal.
    subroutine signals_install()
        call signals_deck('')
        call install(MODE_MAIN)
    end subroutine signals_install

    !> The other ranks of an MPI run: on SIGINT, SIGTERM or SIGHUP wait LINGER_WORKER, then
    !! exit with 128 + the signal, saying nothing (rank 0 speaks).
    subroutine signals_worker()
        call install(MODE_WORKER)
    end subroutine signals_worker

    subroutine install(mode)
        integer, intent(in) :: mode
        type(c_funptr) :: prev
        integer :: k
        sig_mode = mode
        do k = 1, size(HANDLED)
            prev = c_signal(HANDLED(k), c_funloc(on_signal))
        end do
    end subroutine install

    !> An MPI run of several ranks: rank 0's line says where its SIGTERM may come from, and
    !! it lingers after the line (see the module's notes).
    subroutine signals_mpi(ranks)
        integer, intent(in) :: ranks                !! ranks of the run
        if (ranks <= 1) return
        sig_linger = 1
        line_why = '; mpirun passes an interrupt on to every rank as SIGTERM, and sends '// &
            'SIGTERM when a rank dies'
        call compose()
    end subroutine signals_mpi

    ! ================================================================ the line

    !> A new deck (its path as given; '' between decks): no stage, no checkpoint kept yet.
    subroutine signals_deck(deck)
        character(len=*), intent(in) :: deck        !! the deck as given on the command line
        line_deck = deck
        line_stage = ''
        line_kept = ''
        line_sweep = .false.
        if (.not. allocated(line_why)) line_why = ''
        call compose()
    end subroutine signals_deck

    !> The stage the deck is in (an analysis, e.g. 'simulate', or a sweep, e.g. 'chart'); a
    !! sweep that writes checkpoints says so (sweep) until its first one is kept.
    subroutine signals_stage(stage, sweep)
        character(len=*), intent(in) :: stage       !! what is running ('' none)
        logical, intent(in), optional :: sweep      !! a checkpointed sweep
        if (.not. allocated(line_deck)) call signals_deck('')
        line_stage = stage
        line_sweep = .false.
        if (present(sweep)) line_sweep = sweep
        call compose()
    end subroutine signals_stage

    !> The stage the line names now (to put it back after a sweep inside an analysis).
    function signals_stage_now() result(s)
        character(len=:), allocatable :: s
        s = ''
        if (allocated(line_stage)) s = line_stage
    end function signals_stage_now

    !> A checkpoint is kept at path from now on (for this deck): the line says so.
    subroutine signals_kept(path)
        character(len=*), intent(in) :: path        !! the checkpoint
        if (.not. allocated(line_deck)) call signals_deck('')
        line_kept = path
        call compose()
    end subroutine signals_kept

    !> Put the line together from its parts into the buffer not in use, then use it:
    !! 'bifilar: error (interrupted): DECK: STAGE stopped by signal ' N ' (NAME)' WHY TAIL.
    subroutine compose()
        character(len=:), allocatable :: pre, post
        integer :: b
        if (.not. allocated(line_deck)) return
        pre = 'bifilar: error (interrupted): '
        if (len(line_deck) > 0) pre = pre//line_deck//': '
        if (len(line_stage) > 0) pre = pre//line_stage//' '
        pre = pre//'stopped by signal '
        post = ''
        if (allocated(line_why)) post = line_why
        if (len(line_kept) > 0) then
            post = post//'; the points of the last checkpoint are kept in '//line_kept// &
                ': run again with --resume to continue'
        else if (line_sweep) then
            post = post//'; stopped before its first checkpoint: nothing is kept'
        else if (len(line_deck) > 0) then
            post = post//'; nothing is kept'
        end if
        b = 3 - sig_active
        call put(pre, sig_pre(:, b), sig_pre_len(b))
        call put(post//achar(10), sig_post(:, b), sig_post_len(b))
        sig_active = b
    end subroutine compose

    !> Copy s into a buffer (cut at its capacity, keeping the last character: the newline).
    subroutine put(s, buf, n)
        character(len=*), intent(in) :: s
        character(kind=c_char), volatile, intent(inout) :: buf(:)
        integer, volatile, intent(inout) :: n
        integer :: k, m
        m = min(len(s), size(buf))
        do k = 1, m - 1
            buf(k) = s(k:k)
        end do
        if (m > 0) buf(m) = s(len(s):len(s))
        n = m
    end subroutine put

    ! ================================================================ temporary files

    !> The temporary file at path is about to be created: the handler removes it from now
    !! on (until signals_untrack).  Call before creating it.  Waits for the end when the
    !! process is ending.
    subroutine signals_track(path)
        character(len=*), intent(in) :: path        !! its (temporary) name
        integer :: k, i
        if (sig_ending /= 0) call wait_for_end()
        if (len(path) >= PATH_CAP) return           ! (no system takes such a path)
        do k = 1, NSLOTS
            if (slot_used(k) /= 0) cycle
            do i = 1, len(path)
                slot_path(i, k) = path(i:i)
            end do
            slot_path(len(path) + 1, k) = c_null_char
            slot_used(k) = 1
            return
        end do
    end subroutine signals_track

    !> The temporary file at path is renamed or removed: the handler leaves the name alone.
    subroutine signals_untrack(path)
        character(len=*), intent(in) :: path        !! its (temporary) name
        integer :: k, i
        logical :: same
        do k = 1, NSLOTS
            if (slot_used(k) == 0) cycle
            if (len(path) >= PATH_CAP) cycle
            if (slot_path(len(path) + 1, k) /= c_null_char) cycle
            same = .true.
            do i = 1, len(path)
                if (slot_path(i, k) /= path(i:i)) then
                    same = .false.
                    exit
                end if
            end do
            if (same) slot_used(k) = 0
        end do
    end subroutine signals_untrack

    !> The tracked file at path has just been created: when a handler began meanwhile (it
    !! may have looked for the file before it existed), remove it and wait for the end.
    subroutine signals_created(path)
        character(len=*), intent(in) :: path        !! its (temporary) name
        integer(c_int) :: rc
        if (sig_ending == 0) return
        rc = c_unlink(path//c_null_char)
        call wait_for_end()
    end subroutine signals_created

    !> The process is ending (a handler runs on another thread): wait for its _exit.
    subroutine wait_for_end()
        integer(c_long) :: req(2), rem(2)
        integer(c_int) :: rc
        req = [0_c_long, 10000000_c_long]
        do
            rc = c_nanosleep(req, rem)
        end do
    end subroutine wait_for_end

    ! ================================================================ deferring

    !> From now on a signal is only noted, and acted on at signals_release (a deck's files
    !! are being renamed into place and its line printed).
    subroutine signals_defer()
        sig_defer = 1
    end subroutine signals_defer

    !> Act on a signal noted since signals_defer (when signals are not ignored by then), and
    !! act on signals at once again.
    subroutine signals_release()
        integer :: s
        sig_defer = 0
        s = sig_pending
        sig_pending = 0
        if (s /= 0 .and. sig_ignore == 0 .and. sig_mode /= MODE_NONE) &
            call on_signal(int(s, c_int))
    end subroutine signals_release

    !> The run is complete (every line printed): signals are ignored from now on, and one
    !! noted meanwhile is dropped.
    subroutine signals_ignore()
        sig_ignore = 1
        sig_pending = 0
    end subroutine signals_ignore

    ! ================================================================ the handler

    !> The signal handler: async-signal-safe (unlink, write, nanosleep, _exit; no memory is
    !! allocated, only fixed arrays are read and written).
    recursive subroutine on_signal(sig) bind(C)
        integer(c_int), value :: sig                !! the signal's number
        integer(c_size_t) :: rc
        integer(c_int) :: rcu
        integer(c_long) :: req(2), rem(2)
        integer :: k, i, n, b, s, nd, w
        character(kind=c_char) :: digits(4)
        character(kind=c_char) :: p(PATH_CAP)
        if (sig_ignore /= 0) return
        if (sig_mode == MODE_NONE) return
        if (sig_defer /= 0) then
            if (sig_pending == 0) sig_pending = sig
            return
        end if
        req(1) = 0
        if (sig_mode == MODE_WORKER) then
            req(2) = LINGER_WORKER
            rcu = c_nanosleep(req, rem)
            call c_exit_now(128_c_int + sig)
        end if
        sig_ending = 1
        ! the temporary files
        do k = 1, NSLOTS
            if (slot_used(k) == 0) cycle
            do i = 1, PATH_CAP
                p(i) = slot_path(i, k)
                if (p(i) == c_null_char) exit
            end do
            p(PATH_CAP) = c_null_char
            rcu = c_unlink(p)
        end do
        ! the line: pre, the number, ' (NAME)', post
        b = sig_active
        n = 0
        do i = 1, sig_pre_len(b)
            n = n + 1
            sig_out(n) = sig_pre(i, b)
        end do
        s = sig
        nd = 0
        do while (nd < 4)
            nd = nd + 1
            digits(5 - nd) = achar(48 + mod(s, 10))
            s = s/10
            if (s == 0) exit
        end do
        do i = 5 - nd, 4
            n = n + 1
            sig_out(n) = digits(i)
        end do
        w = 0
        do k = 1, size(HANDLED)
            if (HANDLED(k) == sig) w = k
        end do
        if (w > 0) then
            n = n + 1
            sig_out(n) = ' '
            n = n + 1
            sig_out(n) = '('
            do i = 1, len_trim(NAMES(w))
                n = n + 1
                sig_out(n) = NAMES(w)(i:i)
            end do
            n = n + 1
            sig_out(n) = ')'
        end if
        do i = 1, sig_post_len(b)
            n = n + 1
            sig_out(n) = sig_post(i, b)
        end do
        if (sig_post_len(b) == 0) then
            n = n + 1
            sig_out(n) = achar(10)
        end if
        rc = c_write(2_c_int, sig_out, int(n, c_size_t))
        req(2) = LINGER_RANK0
        if (sig_linger /= 0) rcu = c_nanosleep(req, rem)
        call c_exit_now(128_c_int + sig)
    end subroutine on_signal

end module signals
