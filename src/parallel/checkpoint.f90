!> The checkpoint of a sweep, OUTDIR/NAME.ANALYSIS.partial: the points a sweep has completed,
!! from which `--resume` continues an interrupted run (module sweep_engine decides when to
!! write it).
!!
!! The file is text: a comment line; the header `format 2`, `analysis ANALYSIS`, `points N`,
!! `values M`, `deck_crc64 HEX`, `exe_crc64 HEX`; `done K`; K records `i HEX ... HEX CRC`,
!! the completed points in increasing order, each value as the 16 hexadecimal digits of its
!! 64-bit pattern (every bit is kept), and CRC the CRC-64 of the record's text before it
!! (`i HEX ... HEX`); `end`.  The header is the sweep's fingerprint: the analysis, the
!! number of points and values, the CRC-64 of the deck file's bytes (and of the sweep's
!! payload, when the task needs more than the deck) and of the executable
!! (/proc/self/exe; module crc64).
!!
!! `checkpoint_write` writes it through a temporary file and a rename (module output_io, whose
!! temporary files the signal handler removes), so the file is always whole; once written,
!! the handler's line says a checkpoint is kept (module signals).  `checkpoint_read` reads
!! only a regular file of a size a checkpoint of the sweep can have (module whole_file: a
!! FIFO or a device is never opened), takes its header only when the whole fingerprint
!! matches, and otherwise says why not (none, not a file, another format, analysis, deck,
!! executable or sweep, damaged): such a checkpoint is ignored (and replaced by the next
!! one).  Of a header it takes, it takes each record whose checksum holds and counts the
!! others; the caller checks the values themselves (sweep_engine: as if computed).
module checkpoint
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_IO
    use text, only: itoa
    use output_io, only: atomic_open, atomic_commit
    use crc64, only: hex16, unhex16, crc64_of
    use signals, only: signals_kept
    use whole_file, only: read_whole_file, FILE_MISSING, FILE_NOT_REGULAR, FILE_TOO_LARGE, &
        FILE_UNREADABLE
    implicit none
    private

    public :: checkpoint_path, checkpoint_write, checkpoint_read

    !> The version of the file's layout (its `format` line).
    integer, parameter :: CHECKPOINT_FORMAT = 2

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
        integer :: u, ios, i, k, nb, nv, r0
        type(status_t) :: st
        character(len=:), allocatable :: block
        character(len=17) :: hex
        integer, parameter :: BLOCK_BYTES = 32768
        stat%code = STATUS_OK
        nv = size(values, 1)
        call atomic_open(path, u, st)
        if (st%code /= STATUS_OK) then
            call set_error(stat, ERR_IO, analysis//': checkpoint: '//st%msg)
            return
        end if
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
            r0 = nb + 1
            call put(itoa(i))
            do k = 1, nv
                hex(1:1) = ' '
                hex(2:17) = hex16(transfer(values(k, i), 0_int64))
                call put(hex)
            end do
            hex(1:1) = ' '
            hex(2:17) = hex16(crc64_of(block(r0:nb)))
            call put(hex)
            call put(achar(10))
            if (nb >= BLOCK_BYTES) call flush_block()
        end do
        call flush_block()
        if (ios == 0) write (u, '(a)', iostat=ios) 'end'
        call atomic_commit(u, path, st, ios)
        if (st%code /= STATUS_OK) then
            call set_error(stat, ERR_IO, analysis//': checkpoint: '//st%msg)
            return
        end if
        call signals_kept(path)

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

    !> For --resume: when the checkpoint at path is a regular file whose header is whole and
    !! whose fingerprint is (analysis, size(done) points, size(values, 1) values, deck_crc,
    !! exe_crc), take its records whose checksum holds into done and values (the other
    !! points: not done, 0), their number into ndone and the number of records that are
    !! damaged or missing (a checksum that fails, a line that is no record, an index out of
    !! order or range, records missing from a file cut short) into nbad.  Otherwise leave
    !! done and values as they are, set ndone and nbad to 0 and say why in note ('' when
    !! the header was taken).  The file's type and size are checked before it is opened: a
    !! FIFO, a device (a symbolic link to /dev/zero), a folder, or a file larger than a
    !! checkpoint of this sweep can be, is not read at all.
    subroutine checkpoint_read(path, analysis, deck_crc, exe_crc, values, done, ndone, nbad, &
                               note)
        character(len=*), intent(in) :: path        !! the checkpoint
        character(len=*), intent(in) :: analysis    !! e.g. 'chart'
        integer(int64), intent(in) :: deck_crc      !! the deck's part of the fingerprint
        integer(int64), intent(in) :: exe_crc       !! the executable's
        real(dp), intent(inout) :: values(:, :)     !! (values, points)
        logical, intent(inout) :: done(:)           !! the points completed
        integer, intent(out) :: ndone               !! points taken
        integer, intent(out) :: nbad                !! records damaged or missing
        character(len=:), allocatable, intent(out) :: note  !! why none were ('' taken)
        integer :: n, nv, nd, i, k, last, p, q, res, pos, ios, nrec, maxline
        integer(int64) :: max_bytes, bits, crc
        character(len=:), allocatable :: bytes, line, kind
        character(len=64) :: head(6)
        character(len=10), parameter :: KEYS(6) = [character(len=10) :: 'format', &
            'analysis', 'points', 'values', 'deck_crc64', 'exe_crc64']
        logical :: ok
        real(dp), allocatable :: vals(:, :)
        real(dp) :: row(size(values, 1))
        logical, allocatable :: got(:)
        note = ''
        ndone = 0
        nbad = 0
        i = 0
        n = size(done)
        nv = size(values, 1)
        ! the longest record line and the largest file this sweep's checkpoint can be
        maxline = len(itoa(n)) + 17*(nv + 1)
        max_bytes = 4096_int64 + int(n, int64)*int(maxline + 1, int64)
        call read_whole_file(path, max_bytes, bytes, res, kind)
        select case (res)
        case (FILE_MISSING)
            note = 'no checkpoint to resume'
            return
        case (FILE_NOT_REGULAR)
            note = 'the checkpoint is not a regular file (a '//kind//')'
            return
        case (FILE_TOO_LARGE)
            note = 'the checkpoint is larger than one of this sweep can be'
            return
        case (FILE_UNREADABLE)
            note = 'the checkpoint cannot be read'
            return
        end select
        pos = 1
        note = 'the checkpoint is damaged'
        parse: block
            if (.not. next_line(512)) exit parse
            if (index(line, '#') /= 1) exit parse
            ! the header, then what differs, the deck's contents first
            do k = 1, size(KEYS)
                if (.not. next_line(len(head(k)) + len_trim(KEYS(k)) + 1)) exit parse
                if (index(line, trim(KEYS(k))//' ') /= 1) exit parse
                head(k) = line(len_trim(KEYS(k)) + 2:)
            end do
            if (head(1) /= itoa(CHECKPOINT_FORMAT)) then
                note = 'the checkpoint is of another format'
                exit parse
            end if
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
            if (.not. next_line(32)) exit parse
            if (index(line, 'done ') /= 1) exit parse
            read (line(6:), *, iostat=ios) nd
            if (ios /= 0 .or. nd < 0 .or. nd > n) exit parse
            note = ''
            allocate (vals(nv, n), got(n))
            got = .false.
            vals = 0.0_dp
            last = 0
            nrec = 0
            ! the records: each whole, with its checksum, in increasing order; a bad one is
            ! dropped (its point is computed again)
            do
                if (.not. next_line(maxline)) exit
                if (line == 'end') exit
                nrec = nrec + 1
                if (nrec > nd) then
                    nbad = nbad + 1
                    cycle
                end if
                ok = len(line) > 17*(nv + 1)
                if (ok) ok = line(len(line) - 16:len(line) - 16) == ' '
                if (ok) then
                    call unhex16(line(len(line) - 15:), crc, ok)
                    if (ok) ok = crc == crc64_of(line(1:len(line) - 17))
                end if
                if (ok) then
                    p = index(line, ' ')
                    ok = p > 1 .and. p - 1 + 17*(nv + 1) == len(line)
                end if
                if (ok) then
                    read (line(1:p - 1), *, iostat=ios) i
                    ok = ios == 0 .and. verify(line(1:p - 1), '0123456789') == 0
                    if (ok) ok = i > last .and. i <= n
                end if
                if (ok) then
                    do q = 1, nv
                        if (line(p + 17*(q - 1):p + 17*(q - 1)) /= ' ') ok = .false.
                        call unhex16(line(p + 17*(q - 1) + 1:p + 17*q), bits, ok)
                        row(q) = transfer(bits, 0.0_dp)
                    end do
                end if
                if (.not. ok) then
                    nbad = nbad + 1
                    cycle
                end if
                vals(:, i) = row
                got(i) = .true.
                last = i
            end do
            nbad = nbad + max(0, nd - nrec)         ! cut short, or fewer than it said
            values = vals
            done = got
            ndone = count(got)
        end block parse

    contains

        !> The next line of bytes (from pos) into line, cut after maxlen + 1 characters (a
        !! line longer than maxlen is then no line the caller takes); false at the end.
        logical function next_line(maxlen)
            integer, intent(in) :: maxlen
            integer :: e
            next_line = .false.
            if (pos > len(bytes)) return
            e = index(bytes(pos:), achar(10))
            if (e == 0) then
                e = len(bytes) + 1
            else
                e = pos + e - 1
            end if
            line = bytes(pos:min(e - 1, pos + maxlen))
            pos = e + 1
            next_line = .true.
        end function next_line

    end subroutine checkpoint_read

end module checkpoint
