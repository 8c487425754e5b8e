!> CRC-64 fingerprints of bytes: of a string, of a file, of a deck with a sweep's payload
!! and of this process's executable, and the ways a 64-bit fingerprint travels: as 16
!! hexadecimal digits (in a checkpoint, in a message to the user) and as two reals (in a
!! message between ranks, module parallel).
!!
!! The CRC is CRC-64/XZ: the polynomial of ECMA-182, reflected, initial value and final xor
!! all ones ("123456789" gives 995DC9BBDF1939FA).  A CRC can be continued over more bytes
!! (`crc64_of(b, crc64_of(a))` is the CRC of a followed by b), which is how a file is read
!! in pieces and how a deck's CRC takes in a sweep's payload.
!!
!! The module keeps no state: crc64_of builds its tables of remainders at each call (a
!! small cost beside the bytes it is used on: a file is taken a MiB at a time), and
!! executable_crc reads the executable at each call (the sweeps call it once per sweep).
module crc64
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    implicit none
    private

    public :: crc64_of, file_crc, deck_crc, executable_crc, crc_parts, crc_join, hex16, unhex16

contains

    !> CRC-64 of the bytes of s, continuing from crc (a previous result) when given.
    !! Eight bytes at a time through eight tables ("slicing by 8": the remainder of a byte
    !! followed by 0 ... 7 zero bytes), then byte by byte: about 1 ns a byte, so that the
    !! executable's fingerprint costs a few ms per sweep.
    pure function crc64_of(s, crc) result(r)
        character(len=*), intent(in) :: s           !! the bytes
        integer(int64), intent(in), optional :: crc !! the CRC of the bytes before s
        integer(int64) :: r
        integer(int64) :: table(0:255, 0:7), x
        integer :: k, j, n8
        table = crc_tables()
        r = not(0_int64)
        if (present(crc)) r = not(crc)
        n8 = 8*(len(s)/8)
        do k = 1, n8, 8
            x = 0
            do j = 7, 0, -1                         ! the 8 bytes, little-endian
                x = ior(ishft(x, 8), int(iachar(s(k + j:k + j)), int64))
            end do
            x = ieor(x, r)
            r = ieor(ieor(ieor(table(iand(x, 255_int64), 7), &
                               table(iand(ishft(x, -8), 255_int64), 6)), &
                          ieor(table(iand(ishft(x, -16), 255_int64), 5), &
                               table(iand(ishft(x, -24), 255_int64), 4))), &
                     ieor(ieor(table(iand(ishft(x, -32), 255_int64), 3), &
                               table(iand(ishft(x, -40), 255_int64), 2)), &
                          ieor(table(iand(ishft(x, -48), 255_int64), 1), &
                               table(iand(ishft(x, -56), 255_int64), 0))))
        end do
        do k = n8 + 1, len(s)
            r = ieor(table(iand(ieor(r, int(iachar(s(k:k)), int64)), 255_int64), 0), &
                     ishft(r, -8))
        end do
        r = not(r)
    end function crc64_of

    !> The tables of crc64_of: (:, 0) the remainders of the 256 bytes, (:, m) those of a
    !! byte followed by m zero bytes.
    pure function crc_tables() result(table)
        integer(int64) :: table(0:255, 0:7)
        integer(int64) :: poly, c
        integer :: n, k, m
        poly = ior(ishft(int(z'C96C5795', int64), 32), int(z'D7870F42', int64))
        do n = 0, 255
            c = int(n, int64)
            do k = 1, 8
                if (btest(c, 0)) then
                    c = ieor(poly, ishft(c, -1))
                else
                    c = ishft(c, -1)
                end if
            end do
            table(n, 0) = c
        end do
        do m = 1, 7
            do n = 0, 255
                table(n, m) = ieor(ishft(table(n, m - 1), -8), &
                                   table(iand(table(n, m - 1), 255_int64), 0))
            end do
        end do
    end function crc_tables

    !> CRC-64 of a file's bytes (ERR_DECK when it cannot be read).
    subroutine file_crc(path, crc, stat)
        character(len=*), intent(in) :: path        !! the file
        integer(int64), intent(out) :: crc          !! its CRC-64
        type(status_t), intent(out) :: stat         !! ERR_DECK: it cannot be read
        integer :: u, ios
        integer(int64) :: size, pos, m
        character(len=512) :: msg
        character(len=:), allocatable :: buf
        integer(int64), parameter :: CHUNK = 1048576
        stat%code = STATUS_OK
        crc = 0
        msg = ''
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, 'cannot read '//path//': '//trim(msg))
            return
        end if
        inquire (unit=u, size=size)
        allocate (character(len=int(min(max(size, 1_int64), CHUNK))) :: buf)
        pos = 0
        do while (pos < size)
            m = min(CHUNK, size - pos)
            read (u, iostat=ios, iomsg=msg) buf(1:m)
            if (ios /= 0) exit
            crc = crc64_of(buf(1:m), crc)
            pos = pos + m
        end do
        close (u)
        if (ios /= 0) call set_error(stat, ERR_DECK, 'cannot read '//path//': '//trim(msg))
    end subroutine file_crc

    !> The deck's part of a sweep's fingerprint: CRC-64 of the deck's text (when given: the
    !! deck as read into memory, deck_t%text), else of the deck file's bytes, continued over
    !! the bytes of the payload.
    subroutine deck_crc(path, payload, crc, stat, text)
        character(len=*), intent(in) :: path        !! the deck
        real(dp), intent(in) :: payload(:)          !! the sweep's payload (may be empty)
        integer(int64), intent(out) :: crc          !! the fingerprint part
        type(status_t), intent(out) :: stat         !! ERR_DECK: the deck cannot be read
        character(len=*), intent(in), optional :: text  !! the deck's text
        if (present(text)) then
            crc = crc64_of(text)
            stat%code = 0
        else
            call file_crc(path, crc, stat)
        end if
        if (size(payload) > 0) then
            crc = crc64_of(transfer(payload, repeat(' ', 8*size(payload))), crc)
        end if
    end subroutine deck_crc

    !> CRC-64 of this process's executable (/proc/self/exe; 0 where there is none).
    function executable_crc() result(crc)
        integer(int64) :: crc
        type(status_t) :: st
        call file_crc('/proc/self/exe', crc, st)
        if (st%code /= STATUS_OK) crc = 0
    end function executable_crc

    !> 16 hexadecimal digits (upper case) of a 64-bit pattern.
    pure function hex16(x) result(s)
        integer(int64), intent(in) :: x             !! the pattern
        character(len=16) :: s
        character(len=16), parameter :: DIGITS = '0123456789ABCDEF'
        integer :: k, d
        do k = 1, 16
            d = int(ibits(x, 64 - 4*k, 4))
            s(k:k) = DIGITS(d + 1:d + 1)
        end do
    end function hex16

    !> The 64-bit pattern of 16 hexadecimal digits; ok becomes false on any other character.
    pure subroutine unhex16(s, x, ok)
        character(len=16), intent(in) :: s          !! the digits (upper case)
        integer(int64), intent(out) :: x            !! the pattern
        logical, intent(inout) :: ok                !! set false on a bad digit, else unchanged
        integer :: k, d
        x = 0
        do k = 1, 16
            d = index('0123456789ABCDEF', s(k:k)) - 1
            if (d < 0) then
                ok = .false.
                return
            end if
            x = ior(ishft(x, 4), int(d, int64))
        end do
    end subroutine unhex16

    !> A 64-bit pattern as two reals (its 32-bit halves), exact in a message.
    pure function crc_parts(x) result(r)
        integer(int64), intent(in) :: x             !! the pattern
        real(dp) :: r(2)
        r = [real(ibits(x, 32, 32), dp), real(ibits(x, 0, 32), dp)]
    end function crc_parts

    !> The inverse of crc_parts.
    pure function crc_join(r) result(x)
        real(dp), intent(in) :: r(2)                !! the two halves
        integer(int64) :: x
        x = ior(ishft(int(r(1), int64), 32), int(r(2), int64))
    end function crc_join

end module crc64
