!> What a real input variable may be: a closed range [low, high] or low < x
!> <= high, finite, in a unit shown in messages.
module io_input_bounds
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use base_kinds, only: wp
  use io_declaration, only: bound_text
  implicit none (type, external)
  private
  public :: bounds_t, in_range, above

  !> What a real variable may be: low <= x <= high, or low < x <= high.
  type :: bounds_t
    real(wp) :: low = -huge(1.0_wp), high = huge(1.0_wp)
    logical :: open_low = .false.
    character(len=:), allocatable :: unit
  contains
    procedure :: allows => bounds_allow
    procedure :: text => bounds_text
  end type bounds_t

contains

  !> low <= x <= high, in `unit` (shown in messages).
  pure function in_range(low, high, unit) result(b)
    real(wp), intent(in) :: low, high
    character(len=*), intent(in) :: unit
    type(bounds_t) :: b
    b%low = low
    b%high = high
    b%unit = unit
  end function in_range

  !> low < x <= high, in `unit`.
  pure function above(low, high, unit) result(b)
    real(wp), intent(in) :: low, high
    character(len=*), intent(in) :: unit
    type(bounds_t) :: b
    b = in_range(low, high, unit)
    b%open_low = .true.
  end function above

  elemental logical function bounds_allow(self, x)
    class(bounds_t), intent(in) :: self
    real(wp), intent(in) :: x
    bounds_allow = .false.
    if (.not. ieee_is_finite(x)) return
    if (x > self%high) return
    if (self%open_low) then
      bounds_allow = x > self%low
    else
      bounds_allow = x >= self%low
    end if
  end function bounds_allow

  pure function bounds_text(self) result(text)
    class(bounds_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (self%open_low) then
      text = 'must be a finite number > '//bound_text(self%low)//' and <= '//bound_text(self%high)
    else
      text = 'must be a finite number in ['//bound_text(self%low)//', '//bound_text(self%high)//']'
    end if
    if (allocated(self%unit)) then
      if (len(self%unit) > 0) text = text//' ('//self%unit//')'
    end if
  end function bounds_text
end module io_input_bounds
