!> Messages and progress output of long runs, on standard error so that
!> standard output stays for summaries. Standard output is flushed before each
!> message: where both streams go to one file or pipe, every line stays in
!> the order it was written (a summary's last line before the error after it).
!> Quiet until the program asks: verbosity is 0 until set_verbosity (the
!> slidesim command sets 1, or 0 with -q), so a program using the library
!> sees no line it did not ask for. Library code writes only through a
!> log_sink_i its caller passes (the command passes log_info).
module base_log
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: log_info, log_warning, log_error, log_progress, set_verbosity, verbosity
  public :: set_progress_interval, progress_interval, log_sink_i

  integer :: verbosity = 0   !< 0 quiet, 1 normal, 2 verbose; set once from the command line
  !> wall-clock seconds between two progress lines of a long run; set once
  !> from the command line (slidesim --progress)
  real(wp) :: progress_seconds = 2

  abstract interface
    !> Where a library run sends its progress lines when its caller gives
    !> one (log_info is one: standard error, as the command does).
    subroutine log_sink_i(message)
      character(len=*), intent(in) :: message
    end subroutine log_sink_i
  end interface

contains

  subroutine set_verbosity(level)
    integer, intent(in) :: level
    verbosity = level
  end subroutine set_verbosity

  subroutine set_progress_interval(seconds)
    real(wp), intent(in) :: seconds
    progress_seconds = seconds
  end subroutine set_progress_interval

  !> Wall-clock seconds between two progress lines (2 unless set).
  function progress_interval() result(seconds)
    real(wp) :: seconds
    seconds = progress_seconds
  end function progress_interval

  subroutine log_info(message)
    character(len=*), intent(in) :: message
    if (verbosity < 1) return
    flush (output_unit)
    write (error_unit, '(a)') message
  end subroutine log_info

  subroutine log_warning(message)
    character(len=*), intent(in) :: message
    flush (output_unit)
    write (error_unit, '(a)') 'warning: '//message
  end subroutine log_warning

  subroutine log_error(message)
    character(len=*), intent(in) :: message
    flush (output_unit)
    write (error_unit, '(a)') 'error: '//message
  end subroutine log_error

  !> One progress line, at most about every tenth of the run.
  subroutine log_progress(label, done, total)
    character(len=*), intent(in) :: label
    real(wp), intent(in) :: done, total
    if (verbosity >= 1 .and. total > 0) then
      flush (output_unit)
      write (error_unit, '(a, ": ", f5.1, " %")') label, 100*min(1.0_wp, done/total)
      flush (error_unit)
    end if
  end subroutine log_progress
end module base_log
