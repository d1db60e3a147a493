!> The change of variables that holds bounds exactly in the least-squares fit
!> (numerics_least_squares, whose module comment gives the formulas): each
!> parameter's kind of bounds, p = P(z) with dP/dz, its inverse, the start moved
!> off the bounds, and the test for an optimum near a bound.
module numerics_bounded_variables
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: KIND_FREE, KIND_LOWER, KIND_UPPER, KIND_BOTH, KIND_FIXED
  public :: bound_kind, has_lower, has_upper, near_lower, near_upper, start_inside, to_p, to_z

  integer, parameter :: KIND_FREE = 0, KIND_LOWER = 1, KIND_UPPER = 2, KIND_BOTH = 3, &
                        KIND_FIXED = 4

contains

  elemental integer function bound_kind(lower, upper) result(kind)
    real(wp), intent(in) :: lower, upper
    logical :: lo, up
    lo = lower > -huge(lower)
    up = upper < huge(upper)
    if (lo .and. up .and. lower == upper) then
      kind = KIND_FIXED
    else if (lo .and. up) then
      kind = KIND_BOTH
    else if (lo) then
      kind = KIND_LOWER
    else if (up) then
      kind = KIND_UPPER
    else
      kind = KIND_FREE
    end if
  end function bound_kind

  elemental logical function has_lower(kind)
    integer, intent(in) :: kind
    has_lower = kind == KIND_LOWER .or. kind == KIND_BOTH
  end function has_lower

  elemental logical function has_upper(kind)
    integer, intent(in) :: kind
    has_upper = kind == KIND_UPPER .or. kind == KIND_BOTH
  end function has_upper

  !> p lies within tolerance max(1, |lower|) of a lower bound it has.
  elemental logical function near_lower(kind, p, lower, tolerance)
    integer, intent(in) :: kind
    real(wp), intent(in) :: p, lower, tolerance
    near_lower = .false.
    if (has_lower(kind)) near_lower = p - lower <= tolerance*max(1.0_wp, abs(lower))
  end function near_lower

  !> p lies within tolerance max(1, |upper|) of an upper bound it has.
  elemental logical function near_upper(kind, p, upper, tolerance)
    integer, intent(in) :: kind
    real(wp), intent(in) :: p, upper, tolerance
    near_upper = .false.
    if (has_upper(kind)) near_upper = upper - p <= tolerance*max(1.0_wp, abs(upper))
  end function near_upper

  !> The start clamped into the box and moved off the bounds by 1e-3 of the
  !> range (two bounds) or of max(1, |bound|) (one bound).
  elemental real(wp) function start_inside(p, lower, upper, kind) result(q)
    real(wp), intent(in) :: p, lower, upper
    integer, intent(in) :: kind
    real(wp), parameter :: margin = 1e-3_wp
    q = p
    select case (kind)
    case (KIND_BOTH)
      q = min(upper - margin*(upper - lower), max(lower + margin*(upper - lower), p))
    case (KIND_LOWER)
      q = max(lower + margin*max(1.0_wp, abs(lower)), p)
    case (KIND_UPPER)
      q = min(upper - margin*max(1.0_wp, abs(upper)), p)
    case (KIND_FIXED)
      q = lower
    end select
  end function start_inside

  !> p = P(z) and dP/dz (see the module comment).
  pure subroutine to_p(kind, lower, upper, z, p, dpdz)
    integer, intent(in) :: kind
    real(wp), intent(in) :: lower, upper, z
    real(wp), intent(out) :: p, dpdz
    real(wp) :: s, c, h
    select case (kind)
    case (KIND_BOTH)
      c = (lower + upper)/2
      h = (upper - lower)/2
      p = min(upper, max(lower, c + h*sin((z - c)/h)))
      dpdz = cos((z - c)/h)
    case (KIND_LOWER)
      s = sqrt(1 + z**2)
      p = lower + z**2/(1 + s)
      dpdz = z/s
    case (KIND_UPPER)
      s = sqrt(1 + z**2)
      p = upper - z**2/(1 + s)
      dpdz = -z/s
    case (KIND_FIXED)
      p = lower
      dpdz = 0
    case default
      p = z
      dpdz = 1
    end select
  end subroutine to_p

  !> z with P(z) = p, for p inside the box.
  pure real(wp) function to_z(kind, lower, upper, p) result(z)
    integer, intent(in) :: kind
    real(wp), intent(in) :: lower, upper, p
    real(wp) :: w, c, h
    select case (kind)
    case (KIND_BOTH)
      c = (lower + upper)/2
      h = (upper - lower)/2
      z = c + h*asin(max(-1.0_wp, min(1.0_wp, (p - c)/h)))
    case (KIND_LOWER)
      w = max(0.0_wp, p - lower)
      z = sqrt(w*(w + 2))   ! sqrt(1 + z^2) - 1 = w
    case (KIND_UPPER)
      w = max(0.0_wp, upper - p)
      z = sqrt(w*(w + 2))
    case (KIND_FIXED)
      z = 0
    case default
      z = p
    end select
  end function to_z
end module numerics_bounded_variables
