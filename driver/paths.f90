!> What a path names (a file, a directory, nothing) and the files a glob pattern matches:
!> POSIX stat() and glob() through driver/glob.c.
module driver_paths
    use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_null_char, c_associated
    implicit none
    private

    public :: path_kind, glob_files, has_glob_chars, string_t
    public :: PATH_NONE, PATH_FILE, PATH_DIR, PATH_OTHER

    !> What path_kind finds: nothing (or it cannot be reached), a regular file, a
    !> directory, something else (a device, a FIFO, a socket).
    integer, parameter :: PATH_NONE = 0, PATH_FILE = 1, PATH_DIR = 2, PATH_OTHER = 3

    !> One string of a list.
    type :: string_t
        character(len=:), allocatable :: s
    end type string_t

    interface
        function sp_glob_open(pattern, status) bind(c, name='sp_glob_open') result(h)
            import :: c_char, c_int, c_ptr
            character(kind=c_char), intent(in) :: pattern(*)
            integer(c_int), intent(out) :: status
            type(c_ptr) :: h
        end function sp_glob_open
        subroutine sp_glob_count(h, n, n_dirs) bind(c, name='sp_glob_count')
            import :: c_int, c_ptr
            type(c_ptr), value :: h
            integer(c_int), intent(out) :: n, n_dirs
        end subroutine sp_glob_count
        integer(c_int) function sp_glob_length(h, i) bind(c, name='sp_glob_length')
            import :: c_int, c_ptr
            type(c_ptr), value :: h
            integer(c_int), value :: i
        end function sp_glob_length
        subroutine sp_glob_copy(h, i, buf, buflen) bind(c, name='sp_glob_copy')
            import :: c_char, c_int, c_ptr
            type(c_ptr), value :: h
            integer(c_int), value :: i, buflen
            character(kind=c_char), intent(out) :: buf(*)
        end subroutine sp_glob_copy
        subroutine sp_glob_close(h) bind(c, name='sp_glob_close')
            import :: c_ptr
            type(c_ptr), value :: h
        end subroutine sp_glob_close
        integer(c_int) function sp_path_kind(path) bind(c, name='sp_path_kind')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
        end function sp_path_kind
    end interface

contains

    !> PATH_NONE, PATH_FILE, PATH_DIR or PATH_OTHER: what `path` names (stat()).
    integer function path_kind(path)
        character(len=*), intent(in) :: path
        path_kind = int(sp_path_kind(path//c_null_char))
    end function path_kind

    !> Whether a name holds a glob character (*, ? or [).
    pure logical function has_glob_chars(name)
        character(len=*), intent(in) :: name
        has_glob_chars = scan(name, '*?[') > 0
    end function has_glob_chars

    !> The files `pattern` matches (POSIX glob: *, ?, [...], \ escapes the next
    !> character), in byte order; directories it matches are left out and counted in
    !> n_dirs. stat: 0 (no match is not an error here: size(paths) = 0), 1 a directory
    !> could not be read, 2 out of memory.
    subroutine glob_files(pattern, paths, n_dirs, stat)
        character(len=*), intent(in) :: pattern
        type(string_t), allocatable, intent(out) :: paths(:)
        integer, intent(out) :: n_dirs, stat
        type(c_ptr) :: h
        integer(c_int) :: st, n, nd
        integer :: i, k
        h = sp_glob_open(pattern//c_null_char, st)
        stat = int(st)
        n_dirs = 0
        if (.not. c_associated(h)) then
            allocate(paths(0))
            return
        end if
        call sp_glob_count(h, n, nd)
        n_dirs = int(nd)
        allocate(paths(n))
        do i = 1, int(n)
            k = int(sp_glob_length(h, int(i, c_int)))
            allocate(character(len=k) :: paths(i)%s)
            if (k > 0) call copy_match(h, i, paths(i)%s)
        end do
        call sp_glob_close(h)
    end subroutine glob_files

    subroutine copy_match(h, i, s)
        type(c_ptr), intent(in) :: h
        integer, intent(in) :: i
        character(len=*), intent(out) :: s
        character(kind=c_char) :: buf(len(s))
        integer :: j
        call sp_glob_copy(h, int(i, c_int), buf, int(len(s), c_int))
        do j = 1, len(s)
            s(j:j) = buf(j)
        end do
    end subroutine copy_match

end module driver_paths
