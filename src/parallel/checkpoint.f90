!> The checkpoint of a sweep, OUTDIR/NAME.ANALYSIS.partial: the points a sweep has completed,
!! from which `--resume` continues an interrupted run (module sweep_engine decides when to
!! write it).
!!
!! The file is text: a comment line; the header `format 1`, `analysis ANALYSIS`, `points N`,
!! `values M`, `deck_crc64 HEX`, `exe_crc64 HEX`; `done K`; K lines `i HEX ... HEX`, the
!! completed points in increasing order, each value as the 16 hexadecimal digits of its
!! 64-bit pattern (every bit is kept); `end`.  The header is the sweep's fingerprint: the
!! analysis, the number of points and values, the CRC-64 of the deck file's bytes (and of
!! the sweep's payload, when the task needs more than the deck) and of the executable
!! (/proc/self/exe; module crc64).
!!
!! `checkpoint_write` writes it through a temporary file and a rename (module output_io), so
!! the file is always whole; while it is written the signal handler removes the temporary
!! file too, and once written the handler's line says a checkpoint is kept (module
!! signals).  `checkpoint_read` takes its points only when the whole fingerprint matches and
!! the file is intact, and otherwise says why not (none, another analysis, deck, executable
!! or sweep, damaged): such a checkpoint is ignored (and replaced by the next one).
module checkpoint
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_IO
    use text, only: itoa
    use output_io, only: atomic_open, atomic_commit
    use crc64, only: hex16, unhex16
    use signals, only: signals_kept, signals_writing, signals_written
    implicit none
    private

    public :: checkpoint_path, checkpoint_write, checkpoint_read

    !> The version of the file's layout (its `format` line).
    integer, parameter :: CHECKPOINT_FORMAT = 1

contains

    !> OUTDIR/NAME.ANALYSIS.partial, the checkpoint of a sweep.
    pure function checkpoint_path(outdir, name, analysis) result(p)
        character(len=*), intent(in) :: outdir      !! the output folder
        character(len=*), intent(in) :: name        !! the deck's name
        character(len=*), intent(in) :: analysis    !! e.g. 'chart'
        character(len=:), allocatable :: p
        p = outdir//'/'//name//'.'//analysis//'.partial'
    end function checkpoint_path

    !> Write the checkpoint at path now (temporary file, then rename): the points i with
    !! done(i), their values values(:, i), under the fingerprint (analysis, size(done) points,
    !! size(values, 1) values, deck_crc, exe_crc).
    subroutine checkpoint_write(path, analysis, deck_crc, exe_crc, values, done, stat)
        character(len=*), intent(in) :: path        !! the checkpoint
        character(len=*), intent(in) :: analysis    !! e.g. 'chart'
        integer(int64), intent(in) :: deck_crc      !! the deck's part of the fingerprint
        integer(int64), intent(in) :: exe_crc       !! the executable's
        real(dp), intent(in) :: values(:, :)        !! (values, points)
        logical, intent(in) :: done(:)              !! the points completed
        type(status_t), intent(out) :: stat         !! ERR_IO: it could not be written
        integer :: u, ios, i, k, nb, nv
        type(status_t) :: st
        character(len=:), allocatable :: block
        character(len=17) :: hex
        character(len=4096) :: tmp
        integer, parameter :: BLOCK_BYTES = 32768
        stat%code = STATUS_OK
        nv = size(values, 1)
        call atomic_open(path, u, st)
        if (st%code /= STATUS_OK) then
            call set_error(stat, ERR_IO, analysis//': checkpoint: '//st%msg)
            return
        end if
        tmp = ''
        inquire (unit=u, name=tmp)
        call signals_writing(trim(tmp))
        write (u, '(a)', iostat=ios) '# bifilar sweep checkpoint: the completed points; '// &
            'bifilar --resume continues from it (the fingerprint must match)'
        if (ios == 0) write (u, '(a,i0)', iostat=ios) 'format ', CHECKPOINT_FORMAT
        if (ios == 0) write (u, '(a)', iostat=ios) 'analysis '//analysis
        if (ios == 0) write (u, '(a,i0)', iostat=ios) 'points ', size(done)
        if (ios == 0) write (u, '(a,i0)', iostat=ios) 'values ', nv
        if (ios == 0) write (u, '(a)', iostat=ios) 'deck_crc64 '//hex16(deck_crc)
        if (ios == 0) write (u, '(a)', iostat=ios) 'exe_crc64 '//hex16(exe_crc)
        if (ios == 0) write (u, '(a,i0)', iostat=ios) 'done ', count(done)
        allocate (character(len=BLOCK_BYTES + 32*(nv + 1)) :: block)
        nb = 0
        do i = 1, size(done)
            if (.not. done(i)) cycle
            call put(itoa(i))
            do k = 1, nv
                hex(1:1) = ' '
                hex(2:17) = hex16(transfer(values(k, i), 0_int64))
                call put(hex)
            end do
            call put(achar(10))
            if (nb >= BLOCK_BYTES) call flush_block()
        end do
        call flush_block()
        if (ios == 0) write (u, '(a)', iostat=ios) 'end'
        call atomic_commit(u, path, st, ios)
        call signals_written()
        if (st%code /= STATUS_OK) then
            call set_error(stat, ERR_IO, analysis//': checkpoint: '//st%msg)
            return
        end if
        call signals_kept()

    contains

        subroutine put(s)
            character(len=*), intent(in) :: s
            block(nb + 1:nb + len(s)) = s
            nb = nb + len(s)
        end subroutine put

        !> The lines gathered so far as one record (its own newline ends the last line).
        subroutine flush_block()
            if (nb > 0 .and. ios == 0) write (u, '(a)', iostat=ios) block(1:nb - 1)
            nb = 0
        end subroutine flush_block

    end subroutine checkpoint_write

    !> For --resume: when the checkpoint at path is intact and its fingerprint is (analysis,
    !! size(done) points, size(values, 1) values, deck_crc, exe_crc), take its points into
    !! done and values (the others: not done, 0) and their number into ndone; otherwise leave
    !! done and values as they are, set ndone to 0 and say why in note ('' when taken).
    subroutine checkpoint_read(path, analysis, deck_crc, exe_crc, values, done, ndone, note)
        character(len=*), intent(in) :: path        !! the checkpoint
        character(len=*), intent(in) :: analysis    !! e.g. 'chart'
        integer(int64), intent(in) :: deck_crc      !! the deck's part of the fingerprint
        integer(int64), intent(in) :: exe_crc       !! the executable's
        real(dp), intent(inout) :: values(:, :)     !! (values, points)
        logical, intent(inout) :: done(:)           !! the points completed
        integer, intent(out) :: ndone               !! points taken
        character(len=:), allocatable, intent(out) :: note  !! why none were ('' taken)
        integer :: u, ios, n, nv, nd, i, k, last, p, q
        character(len=64 + 17*size(values, 1)) :: line
        character(len=64) :: head(6)
        character(len=10), parameter :: KEYS(6) = [character(len=10) :: 'format', &
            'analysis', 'points', 'values', 'deck_crc64', 'exe_crc64']
        logical :: exists, ok
        real(dp), allocatable :: vals(:, :)
        logical, allocatable :: got(:)
        integer(int64) :: bits
        note = ''
        ndone = 0
        n = size(done)
        nv = size(values, 1)
        inquire (file=path, exist=exists)
        if (.not. exists) then
            note = 'no checkpoint to resume'
            return
        end if
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) then
            note = 'the checkpoint cannot be read'
            return
        end if
        note = 'the checkpoint is damaged'
        parse: block
            if (.not. next_line('#')) exit parse
            ! the header, then what differs, the deck's contents first
            do k = 1, size(KEYS)
                if (.not. next_line(trim(KEYS(k))//' ')) exit parse
                head(k) = line(len_trim(KEYS(k)) + 2:)
            end do
            if (head(1) /= itoa(CHECKPOINT_FORMAT)) exit parse
            if (head(2) /= analysis) then
                note = 'the checkpoint is of another analysis'
            else if (head(5) /= hex16(deck_crc)) then
                note = 'the checkpoint is of another deck (its CRC-64 differs)'
            else if (head(6) /= hex16(exe_crc)) then
                note = 'the checkpoint is of another executable (its CRC-64 differs)'
            else if (head(3) /= itoa(n) .or. head(4) /= itoa(nv)) then
                note = 'the checkpoint is of another sweep (its number of points differs)'
            end if
            if (index(note, 'damaged') == 0) exit parse
            if (.not. next_line('done ')) exit parse
            read (line(6:), *, iostat=ios) nd
            if (ios /= 0 .or. nd < 0 .or. nd > n) exit parse
            allocate (vals(nv, n), got(n))
            got = .false.
            vals = 0.0_dp
            last = 0
            ok = .true.
            do k = 1, nd
                if (.not. next_line('')) then
                    ok = .false.
                    exit
                end if
                p = index(line, ' ')
                if (p <= 1) then
                    ok = .false.
                    exit
                end if
                read (line(1:p - 1), *, iostat=ios) i
                if (ios /= 0 .or. i <= last .or. i > n .or. &
                    len_trim(line) /= p - 1 + 17*nv) then
                    ok = .false.
                    exit
                end if
                do q = 1, nv
                    if (line(p + 17*(q - 1):p + 17*(q - 1)) /= ' ') ok = .false.
                    call unhex16(line(p + 17*(q - 1) + 1:p + 17*q), bits, ok)
                    vals(q, i) = transfer(bits, 0.0_dp)
                end do
                if (.not. ok) exit parse
                got(i) = .true.
                last = i
            end do
            if (.not. ok) exit parse
            if (.not. next_line('end')) exit parse
            if (len_trim(line) /= 3) exit parse
            values = vals
            done = got
            ndone = nd
            note = ''
        end block parse
        close (u)

    contains

        !> Read the next line into line; true when it starts with prefix.
        logical function next_line(prefix)
            character(len=*), intent(in) :: prefix
            line(:) = ''
            read (u, '(a)', iostat=ios) line
            next_line = ios == 0
            if (next_line .and. len(prefix) > 0) next_line = index(line, prefix) == 1
        end function next_line

    end subroutine checkpoint_read

end module checkpoint
