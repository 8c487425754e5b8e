!> Message passing between the processes (ranks) of a run, MPI build (`make mpi`): the
!! interface of src/parallel.f90 on OpenMPI through its Fortran 2008 bindings (mpi_f08).
!! This is the only file of the program that calls MPI.  The Makefile compiles it, as
!! module `parallel`, into bin/bifilar_mpi in place of the serial src/parallel.f90.
!!
!! MPI is started with MPI_THREAD_SERIALIZED: the ranks run OpenMP threads, and whichever
!! thread calls here does so alone (the sweep engine calls inside one critical section).
!! Every send is non-blocking (par_post keeps a copy of the payload until MPI has delivered
!! it), so no rank ever waits on another inside a send; par_poll and par_recv take the
!! messages.  MPI errors keep MPI's default handler (MPI_ERRORS_ARE_FATAL: the job ends).
!!
!! State (module variables, one of the three places src/README.md allows): MPI itself is
!! state of the process (initialised once, by par_start), and so are the facts this module
!! keeps of it: the rank and the number of ranks (`my_rank`, `nranks`, `started`), and the
!! sends MPI has not yet delivered (`pend`, `npend`: each payload's copy must outlive the
!! par_post that started its send, until MPI_Test or MPI_Wait says it is delivered).  The
!! serial build (parallel.f90) keeps none.
module parallel
    use mpi_f08, only: MPI_Init_thread, MPI_Finalize, MPI_Comm_rank, MPI_Comm_size, &
        MPI_Isend, MPI_Iprobe, MPI_Recv, MPI_Test, MPI_Wait, MPI_Get_count, &
        MPI_Get_library_version, MPI_Request, MPI_Status, MPI_COMM_WORLD, &
        MPI_DOUBLE_PRECISION, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_THREAD_SERIALIZED, &
        MPI_STATUS_IGNORE, MPI_MAX_LIBRARY_VERSION_STRING
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_NUMERIC
    use text, only: itoa
    implicit none
    private

    public :: par_start, par_stop, par_rank, par_ranks, par_post, par_poll, par_recv
    public :: par_library

    !> par_poll's `from` for a message from any rank.
    integer, parameter, public :: PAR_ANY = -1

    !> A message on its way: its request and the copy of its payload MPI reads from.
    type :: pending_t
        type(MPI_Request) :: req
        real(dp), allocatable :: buf(:)
    end type pending_t

    !> The sends not yet known to be complete (slots 1..npend); grown by move_alloc of each
    !! payload, so that a payload never moves while MPI reads it.
    type(pending_t), allocatable, target, asynchronous, save :: pend(:)
    integer, save :: npend = 0
    integer, save :: my_rank = 0, nranks = 1
    logical, save :: started = .false.

contains

    !> Begin: MPI_Init_thread with MPI_THREAD_SERIALIZED (ERR_NUMERIC when the library
    !! cannot give that).
    subroutine par_start(stat)
        type(status_t), intent(out) :: stat         !! ERR_NUMERIC: threads not supported
        integer :: provided
        stat%code = STATUS_OK
        call MPI_Init_thread(MPI_THREAD_SERIALIZED, provided)
        call MPI_Comm_rank(MPI_COMM_WORLD, my_rank)
        call MPI_Comm_size(MPI_COMM_WORLD, nranks)
        started = .true.
        if (provided < MPI_THREAD_SERIALIZED) call set_error(stat, ERR_NUMERIC, &
            'the MPI library gives thread support level '//itoa(provided)//', below '// &
            'MPI_THREAD_SERIALIZED ('//itoa(MPI_THREAD_SERIALIZED)//') that the OpenMP '// &
            'threads of a rank need')
    end subroutine par_start

    !> End: wait for the messages still on their way, then MPI_Finalize.
    subroutine par_stop()
        integer :: k
        if (.not. started) return
        do k = 1, npend
            call MPI_Wait(pend(k)%req, MPI_STATUS_IGNORE)
            deallocate (pend(k)%buf)
        end do
        npend = 0
        call MPI_Finalize()
        started = .false.
    end subroutine par_stop

    !> This process's rank, 0 .. par_ranks() - 1.
    integer function par_rank()
        par_rank = my_rank
    end function par_rank

    !> Number of ranks of the run.
    integer function par_ranks()
        par_ranks = nranks
    end function par_ranks

    !> Send buf to rank dest with kind `tag`, without waiting: a copy is kept until MPI has
    !! delivered it (MPI_Isend; completed sends are released here and in par_poll).
    subroutine par_post(dest, tag, buf)
        integer, intent(in) :: dest                 !! receiving rank
        integer, intent(in) :: tag                  !! message kind (>= 0)
        real(dp), intent(in) :: buf(:)              !! payload
        type(pending_t), allocatable :: grown(:)
        integer :: k
        call reap()
        if (.not. allocated(pend)) allocate (pend(16))
        if (npend == size(pend)) then
            allocate (grown(2*npend))
            do k = 1, npend
                grown(k)%req = pend(k)%req
                call move_alloc(pend(k)%buf, grown(k)%buf)
            end do
            call move_alloc(grown, pend)
        end if
        npend = npend + 1
        pend(npend)%buf = buf
        call MPI_Isend(pend(npend)%buf, size(buf), MPI_DOUBLE_PRECISION, dest, tag, &
                       MPI_COMM_WORLD, pend(npend)%req)
    end subroutine par_post

    !> Release the payloads of completed sends (the others keep their slots, in order).
    subroutine reap()
        integer :: k, m
        logical :: done
        m = 0
        do k = 1, npend
            call MPI_Test(pend(k)%req, done, MPI_STATUS_IGNORE)
            if (done) then
                deallocate (pend(k)%buf)
            else
                m = m + 1
                if (m < k) then
                    pend(m)%req = pend(k)%req
                    call move_alloc(pend(k)%buf, pend(m)%buf)
                end if
            end if
        end do
        npend = m
    end subroutine reap

    !> Whether a message from `from` (a rank, or PAR_ANY) has arrived, without waiting
    !! (MPI_Iprobe): its sender, kind and length in reals.
    subroutine par_poll(from, src, tag, n, found)
        integer, intent(in) :: from                 !! sending rank, or PAR_ANY
        integer, intent(out) :: src                 !! its sender
        integer, intent(out) :: tag                 !! its kind
        integer, intent(out) :: n                   !! its length (reals)
        logical, intent(out) :: found               !! a message is there
        type(MPI_Status) :: st
        integer :: source
        call reap()
        source = from
        if (from == PAR_ANY) source = MPI_ANY_SOURCE
        call MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, found, st)
        src = -1
        tag = -1
        n = 0
        if (.not. found) return
        src = st%MPI_SOURCE
        tag = st%MPI_TAG
        call MPI_Get_count(st, MPI_DOUBLE_PRECISION, n)
    end subroutine par_poll

    !> Receive the message par_poll found from src with kind tag.
    subroutine par_recv(src, tag, buf)
        integer, intent(in) :: src                  !! its sender
        integer, intent(in) :: tag                  !! its kind
        real(dp), intent(out) :: buf(:)             !! its payload (length from par_poll)
        call MPI_Recv(buf, size(buf), MPI_DOUBLE_PRECISION, src, tag, MPI_COMM_WORLD, &
                      MPI_STATUS_IGNORE)
    end subroutine par_recv

    !> The MPI library, e.g. 'Open MPI v4.1.4, ...' (its first line).
    function par_library() result(s)
        character(len=:), allocatable :: s
        character(len=MPI_MAX_LIBRARY_VERSION_STRING) :: v
        integer :: n, k
        call MPI_Get_library_version(v, n)
        s = v(1:max(0, min(n, len(v))))
        k = index(s, achar(10))
        if (k > 0) s = s(1:k - 1)
        k = index(s, ', package')
        if (k > 0) s = s(1:k - 1)
    end function par_library

end module parallel
