!> A file read whole into memory only when it is a regular file of bounded size: its type
!! and size are asked of the system (statx(2), following symbolic links) before it is
!! opened, so a FIFO (whose open would block until a writer comes), a device (/dev/zero
!! reads for ever), a folder or a socket is refused at once, and so is a file larger than
!! the caller can use; at most that many bytes are ever read.
!!
!! statx's record (struct statx of <linux/stat.h>) has the same layout on every Linux
!! architecture, unlike struct stat; its mode's type bits are POSIX's S_IFMT.
module whole_file
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_int16_t, c_int32_t, &
        c_int64_t
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    public :: read_whole_file, file_kind

    !> What read_whole_file found.
    integer, parameter, public :: FILE_READ = 0         !! read whole into bytes
    integer, parameter, public :: FILE_MISSING = 1      !! no such file
    integer, parameter, public :: FILE_NOT_REGULAR = 2  !! a folder, FIFO, device or socket
    integer, parameter, public :: FILE_TOO_LARGE = 3    !! larger than the caller's limit
    integer, parameter, public :: FILE_UNREADABLE = 4   !! it cannot be read

    !> struct statx (256 bytes; only mask, mode and size are used).
    type, bind(C) :: statx_t
        integer(c_int32_t) :: mask = 0, blksize = 0
        integer(c_int64_t) :: attributes = 0
        integer(c_int32_t) :: nlink = 0, uid = 0, gid = 0
        integer(c_int16_t) :: mode = 0, spare0 = 0
        integer(c_int64_t) :: ino = 0, size = 0, blocks = 0, attributes_mask = 0
        integer(c_int64_t) :: rest(24) = 0          !! the times, the device, spare
    end type statx_t

    integer(c_int), parameter :: AT_FDCWD = -100_c_int
    integer(c_int), parameter :: STATX_TYPE = 1_c_int, STATX_SIZE = 512_c_int
    integer, parameter :: S_IFMT = int(o'170000'), S_IFREG = int(o'100000'), &
        S_IFDIR = int(o'040000'), S_IFIFO = int(o'010000'), S_IFCHR = int(o'020000'), &
        S_IFBLK = int(o'060000'), S_IFSOCK = int(o'140000')

    interface
        !> statx(2) (glibc >= 2.28).
        integer(c_int) function c_statx(dirfd, path, flags, mask, buf) bind(C, name='statx')
            import :: c_int, c_char, statx_t
            integer(c_int), value :: dirfd
            character(kind=c_char), dimension(*), intent(in) :: path   !! null-terminated
            integer(c_int), value :: flags
            integer(c_int), value :: mask
            type(statx_t), intent(out) :: buf
        end function c_statx
    end interface

contains

    !> The kind of the file at path, following symbolic links: 'missing', 'file', 'folder',
    !! 'FIFO', 'character device', 'block device', 'socket' or 'unknown'; and its size
    !! in bytes (0 when not a file).
    subroutine file_kind(path, kind, size)
        character(len=*), intent(in) :: path        !! the file
        character(len=:), allocatable, intent(out) :: kind
        integer(int64), intent(out) :: size         !! bytes
        type(statx_t) :: sx
        integer :: t
        size = 0
        if (c_statx(AT_FDCWD, path//c_null_char, 0_c_int, ior(STATX_TYPE, STATX_SIZE), &
                    sx) /= 0) then
            kind = 'missing'
            return
        end if
        if (iand(sx%mask, STATX_TYPE) == 0) then
            kind = 'unknown'
            return
        end if
        t = iand(int(sx%mode), S_IFMT)
        select case (t)
        case (S_IFREG)
            kind = 'file'
            if (iand(sx%mask, STATX_SIZE) /= 0) size = sx%size
        case (S_IFDIR)
            kind = 'folder'
        case (S_IFIFO)
            kind = 'FIFO'
        case (S_IFCHR)
            kind = 'character device'
        case (S_IFBLK)
            kind = 'block device'
        case (S_IFSOCK)
            kind = 'socket'
        case default
            kind = 'unknown'
        end select
    end subroutine file_kind

    !> The bytes of the file at path when it is a regular file of at most max_bytes bytes
    !! (result FILE_READ); otherwise bytes = '' and result says why (FILE_MISSING,
    !! FILE_NOT_REGULAR with kind naming what it is, FILE_TOO_LARGE, FILE_UNREADABLE).
    subroutine read_whole_file(path, max_bytes, bytes, result, kind)
        character(len=*), intent(in) :: path        !! the file
        integer(int64), intent(in) :: max_bytes     !! the most the caller takes
        character(len=:), allocatable, intent(out) :: bytes
        integer, intent(out) :: result              !! FILE_*
        character(len=:), allocatable, intent(out), optional :: kind   !! file_kind's
        character(len=:), allocatable :: k
        integer(int64) :: n
        integer :: u, ios
        bytes = ''
        call file_kind(path, k, n)
        if (present(kind)) kind = k
        if (k == 'missing') then
            result = FILE_MISSING
            return
        end if
        if (k /= 'file') then
            result = FILE_NOT_REGULAR
            return
        end if
        if (n > max_bytes) then
            result = FILE_TOO_LARGE
            return
        end if
        result = FILE_UNREADABLE
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        deallocate (bytes)
        allocate (character(len=n) :: bytes)
        if (n > 0) read (u, iostat=ios) bytes
        close (u)
        if (ios /= 0) then
            bytes = ''
            return
        end if
        result = FILE_READ
    end subroutine read_whole_file

end module whole_file
