!> The funnel of a slide chain (geometry_slide_elements' kind = 'funnel'):
!> along the funnel the slide's own section widens about its bottom and
!> narrows again, so that a rider or a raft swinging across it rides up
!> walls of a larger radius and back (the half-open funnel of raft rides,
!> lying along a straight centerline). With s0(v) the slide's section and
!> b = s0(pi/2) its bottom,
!>   s(u, v) = b + a(u) (s0(v) - b),
!>   a(u)    = 1 + sum_k (A_k - 1) B_k(u),
!>   B_k(u)  = S((u - u0_k)/(u1_k - u0_k)) - S((u - u2_k)/(u3_k - u2_k)),
!> S the chain's septic smoothstep (C3, geometry_drop_profile): B_k rises
!> from 0 to 1 over [u0, u1], stays 1 over [u1, u2] and falls back to 0 over
!> [u2, u3]. A_k is the funnel's largest scale (its widest bottom radius over
!> the section's). The bottom stays on the centerline's bottom line (no step
!> for the rider), the section's v range is the slide's, and a, with all its
!> derivatives, is 1, 0, 0, 0 outside the windows: the surface is C3 across
!> every end of a funnel. The u-derivatives are a^(i) (s0 - b); the section
!> underneath must not vary along u itself (one section, not a blend).
module geometry_funnel_section
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_cross_section, only: cross_section_t, section_point_t, extent_intervals, extent_sample_v, &
                                    sampled_extent
  use geometry_drop_profile, only: smoothstep
  implicit none (type, external)
  private
  public :: funnel_section_t, new_funnel_section

  !> v at the bottom of a slide's section (geometry_slide_query's slide_bottom_v)
  real(wp), parameter :: bottom_v = 1.5707963267948966_wp

  type, extends(cross_section_t) :: funnel_section_t
    class(cross_section_t), allocatable :: base   ! the slide's section
    real(wp) :: bottom(2) = 0                     ! m, its bottom (y, z) in the frame
    real(wp), allocatable :: u_ends(:, :)         ! (4, k): u0 .. u3 of funnel k
    real(wp), allocatable :: scale(:)             ! A_k, > 1
    !> The base's points s0 at the extent's samples of v (m; the base does
    !> not vary along u) and whether each evaluated: the extent at any u
    !> from them (unallocated: sampled at each u)
    real(wp), allocatable :: base_samples(:, :)   ! (2, 0:extent_intervals)
    logical, allocatable :: sampled(:)            ! (0:extent_intervals)
  contains
    procedure :: evaluate => funnel_evaluate
    procedure :: extent => funnel_extent
    procedure :: v_range => funnel_range
    procedure :: periodic => funnel_periodic
    procedure :: parameter_unit => funnel_parameter_unit
    procedure :: scale_at => funnel_scale_at
  end type funnel_section_t

contains

  !> The funnels of `u_ends(:, k)` (u0 < u1 <= u2 < u3, in the tube's u)
  !> with largest scales `scale(k)` over the section `base`.
  function new_funnel_section(base, u_ends, scale) result(f)
    class(cross_section_t), intent(in) :: base
    real(wp), intent(in) :: u_ends(:, :), scale(:)
    type(funnel_section_t) :: f
    type(section_point_t) :: p
    type(status_t) :: st
    real(wp) :: a, b
    integer :: i
    allocate (f%base, source=base)
    call base%evaluate(0.0_wp, bottom_v, 0, p, st)
    f%bottom = p%s(:, 0, 0)
    f%u_ends = u_ends
    f%scale = scale
    if (base%varies_along()) return
    call base%v_range(a, b)
    allocate (f%base_samples(2, 0:extent_intervals), f%sampled(0:extent_intervals))
    do i = 0, extent_intervals
      call base%evaluate(0.0_wp, extent_sample_v(a, b, i), 0, p, st)
      f%sampled(i) = st%ok()
      f%base_samples(:, i) = p%s(:, 0, 0)
    end do
  end function new_funnel_section

  !> The largest |s(u, v)| over the extent's samples of v (m): the general
  !> sampled_extent's number, from the base's points kept at construction
  !> (b + a(u) (s0 - b) by funnel_evaluate's operations) instead of
  !> evaluating the base at 181 points for each u.
  pure function funnel_extent(self, u) result(r)
    class(funnel_section_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: r
    real(wp) :: a(0:3), d(2), s(2)
    integer :: i
    if (.not. allocated(self%base_samples)) then
      r = sampled_extent(self, u)
      return
    end if
    call self%scale_at(u, a)
    r = 0
    do i = 0, extent_intervals
      if (.not. self%sampled(i)) cycle
      d = self%base_samples(:, i)
      d = d - self%bottom
      s = a(0)*d
      s = s + self%bottom
      r = max(r, norm2(s))
    end do
  end function funnel_extent

  !> a(u) and its u-derivatives a(0:3).
  pure subroutine funnel_scale_at(self, u, a)
    class(funnel_section_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: a(0:3)
    real(wp) :: rise(0:3), fall(0:3), p, w_rise, w_fall
    integer :: k, m
    a = [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
    do k = 1, size(self%scale)
      associate (e => self%u_ends(:, k))
        if (u <= e(1) .or. u >= e(4)) cycle
        w_rise = e(2) - e(1)
        w_fall = e(4) - e(3)
        call smoothstep((u - e(1))/w_rise, rise, p)
        call smoothstep((u - e(3))/w_fall, fall, p)
        do m = 0, 3
          a(m) = a(m) + (self%scale(k) - 1)*(rise(m)/w_rise**m - fall(m)/w_fall**m)
        end do
      end associate
    end do
  end subroutine funnel_scale_at

  pure subroutine funnel_evaluate(self, u, v, order, p, status)
    class(funnel_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    type(section_point_t) :: s0
    real(wp) :: a(0:3), d(2)
    integer :: i, j
    call self%base%evaluate(u, v, order, s0, status)
    if (.not. status%ok()) return
    call self%scale_at(u, a)
    p%order = order
    do j = 0, order
      d = s0%s(:, 0, j)
      if (j == 0) d = d - self%bottom
      p%s(:, 0, j) = a(0)*d
      if (j == 0) p%s(:, 0, 0) = p%s(:, 0, 0) + self%bottom
      do i = 1, order - j
        p%s(:, i, j) = a(i)*d
      end do
    end do
  end subroutine funnel_evaluate

  pure subroutine funnel_range(self, v_min, v_max)
    class(funnel_section_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    call self%base%v_range(v_min, v_max)
  end subroutine funnel_range

  pure logical function funnel_periodic(self) result(periodic)
    class(funnel_section_t), intent(in) :: self
    periodic = self%base%periodic()
  end function funnel_periodic

  pure function funnel_parameter_unit(self) result(unit)
    class(funnel_section_t), intent(in) :: self
    character(len=:), allocatable :: unit
    unit = self%base%parameter_unit()
  end function funnel_parameter_unit
end module geometry_funnel_section
