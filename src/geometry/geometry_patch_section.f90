!> The free-form patch of a slide chain (geometry_slide_elements' kind =
!> 'patch'): a B-spline surface from points placed on the slide's wall along
!> one element. The user gives the wall's outward offset d_ij (m) from the
!> slide's circle at stations x_i along the element (m of its horizontal
!> length from its start) and angles a_j around the section (deg: 0 the
!> right wall, 90 the bottom, 180 the left wall, 270 the top); the offsets on
!> the grid's border (first and last station, first and last angle) are 0,
!> where the patch meets the plain tube. The section is
!>   s(u, v) = s0(u, v) + f(u, v) n(v),   n(v) = -[cos v, sin v],
!>   f(u, v) = W(u; u_1, u_2, u_n-1, u_n) W(v; v_1, v_2, v_m-1, v_m) d(u, v),
!> s0 the slide's section (a circle, or a flume's round part, whose radius n
!> is), d the quintic interpolating spline through the grid (FITPACK regrid,
!> s = 0) over the tube's u at the stations and v = a in rad, and W the
!> window that rises from 0 to 1 over the first grid interval by the chain's
!> septic smoothstep S (C3, geometry_drop_profile), stays 1, and falls back
!> over the last: W = S((x - x_1)/(x_2 - x_1)) - S((x - x_m-1)/(x_m - x_m-1)).
!> So the wall passes through every given point (at the border d is 0 and so
!> is f; inside W = 1), and f with all its derivatives to the third is 0 on
!> the border: the patch meets the tube before and after it, and beside it,
!> with continuous position, tangent and curvature by construction, and a
!> patch of zero offsets is the plain tube. The derivatives of f are
!> Leibniz's sums of the windows' and the spline's.
module geometry_patch_section
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_OK
  use base_text, only: format_integer, format_short
  use numerics_spline_surface, only: spline_surface_t, spline_surface_eval_t, fit_grid
  use geometry_cross_section, only: cross_section_t, section_point_t, circle_section_t, ellipse_point, &
                                    extent_intervals, extent_sample_v
  use geometry_drop_profile, only: smoothstep
  implicit none (type, external)
  private
  public :: patch_grid_t, patch_offset_t, patch_section_t, new_patch_offset, new_patch_section
  public :: patch_degree, min_patch_lines

  !> The degree of the spline in both directions: quintic, so the wall's
  !> third partials (the tube's) are continuous (C4) inside the patch
  integer, parameter :: patch_degree = 5
  !> The fewest stations and the fewest angles a patch has (a quintic's)
  integer, parameter :: min_patch_lines = patch_degree + 1

  !> A patch as given: the element it lies on (its index in the chain), its
  !> stations (m, increasing), angles (deg, increasing) and offsets
  !> offset(i, j) (m) at station i and angle j; `source` names it in messages
  !> (the input's file; default 'the patch of element k').
  type :: patch_grid_t
    integer :: element = 0
    real(wp), allocatable :: station(:), angle_deg(:), offset(:, :)
    character(len=:), allocatable :: source
  end type patch_grid_t

  !> One patch placed on the tube: d(u, v) and its windows' ends in u and v.
  type :: patch_offset_t
    type(spline_surface_t) :: spline
    real(wp) :: u_ends(4) = 0
    real(wp) :: v_ends(4) = 0
  end type patch_offset_t

  type, extends(cross_section_t) :: patch_section_t
    class(cross_section_t), allocatable :: base   ! the slide's section
    type(patch_offset_t), allocatable :: patches(:)
    !> At the extent's samples of v: the base's points (m; a base that does
    !> not vary along u), whether each evaluated, and n(v) = -[cos v, sin v]:
    !> the extent on a patch from them (unallocated: each point evaluated)
    real(wp), allocatable :: base_samples(:, :), normals(:, :)   ! (2, 0:extent_intervals)
    logical, allocatable :: sampled(:)                           ! (0:extent_intervals)
  contains
    procedure :: evaluate => patch_evaluate
    procedure :: v_range => patch_range
    procedure :: periodic => patch_periodic
    procedure :: parameter_unit => patch_parameter_unit
    procedure :: extent => patch_extent
    procedure :: offset_at => patch_offset_at
  end type patch_section_t

  integer, parameter :: binom(0:3, 0:3) = reshape([1, 0, 0, 0, 1, 1, 0, 0, 1, 2, 1, 0, 1, 3, 3, 1], [4, 4])

contains

  !> The patch `grid` placed at the tube's u = `u(i)` of its stations, on a
  !> section of radius `radius` (m) whose angles may lie in [0, max_angle]
  !> deg; refused (the message names grid%source, the value and what is
  !> allowed): fewer than min_patch_lines stations or angles, lines not
  !> increasing or outside the element's `length` (m) or the angles, an
  !> offset on the border not 0, a wall through the centerline.
  function new_patch_offset(grid, u, length, radius, max_angle, status) result(patch)
    type(patch_grid_t), intent(in) :: grid
    real(wp), intent(in) :: u(:), length, radius, max_angle
    type(status_t), intent(out) :: status
    type(patch_offset_t) :: patch
    integer :: n, m, i, j
    n = size(grid%station)
    m = size(grid%angle_deg)
    if (n < min_patch_lines .or. m < min_patch_lines) then
      call refuse('has '//format_integer(n)//' stations and '//format_integer(m)//' angles: the quintic '// &
                  'spline through it needs at least '//format_integer(min_patch_lines)//' of each')
      return
    end if
    if (any(grid%station(2:) <= grid%station(:n - 1)) .or. any(grid%angle_deg(2:) <= grid%angle_deg(:m - 1))) then
      call refuse('stations and angles must increase')
      return
    end if
    if (grid%station(1) < 0 .or. grid%station(n) > length) then
      call refuse('stations from '//format_short(grid%station(1))//' to '//format_short(grid%station(n))// &
                  ' m: they must lie on the element, in [0, '//format_short(length)//'] m (its horizontal length)')
      return
    end if
    if (grid%angle_deg(1) < 0 .or. grid%angle_deg(m) > max_angle) then
      call refuse('angles from '//format_short(grid%angle_deg(1))//' to '//format_short(grid%angle_deg(m))// &
                  ' deg: they must lie in [0, '//format_short(max_angle)//'] deg around the section')
      return
    end if
    do j = 1, m
      do i = 1, n
        if ((i == 1 .or. i == n .or. j == 1 .or. j == m) .and. grid%offset(i, j) /= 0) then
          call refuse('the offset at station '//format_short(grid%station(i))//' m, angle '// &
                      format_short(grid%angle_deg(j))//' deg is '//format_short(grid%offset(i, j))// &
                      ' m: on the border of the grid (first and last station, first and last angle) it must '// &
                      'be 0, where the patch meets the plain slide')
          return
        end if
        if (.not. radius + grid%offset(i, j) > 0) then
          call refuse('the offset at station '//format_short(grid%station(i))//' m, angle '// &
                      format_short(grid%angle_deg(j))//' deg is '//format_short(grid%offset(i, j))// &
                      ' m: the wall would pass through the centerline (the section''s radius is '// &
                      format_short(radius)//' m); it must be > '//format_short(-radius)//' m')
          return
        end if
      end do
    end do
    patch%spline = fit_grid(u, grid%angle_deg*pi/180, grid%offset, 0.0_wp, patch_degree, patch_degree, status)
    if (.not. status%ok()) then
      call refuse(status%text())
      return
    end if
    patch%u_ends = [u(1), u(2), u(n - 1), u(n)]
    patch%v_ends = [grid%angle_deg(1), grid%angle_deg(2), grid%angle_deg(m - 1), grid%angle_deg(m)]*pi/180

  contains
    subroutine refuse(what)
      character(len=*), intent(in) :: what
      character(len=:), allocatable :: source
      source = 'the patch of element '//format_integer(grid%element)
      if (allocated(grid%source)) source = grid%source
      call set_status(status, STATUS_INVALID_INPUT, source//': '//what)
    end subroutine refuse
  end function new_patch_offset

  !> The section `base` with the patches on it.
  function new_patch_section(base, patches) result(s)
    class(cross_section_t), intent(in) :: base
    type(patch_offset_t), intent(in) :: patches(:)
    type(patch_section_t) :: s
    type(section_point_t) :: p
    type(status_t) :: st
    real(wp) :: a, b, v
    integer :: i
    allocate (s%base, source=base)
    s%patches = patches
    if (base%varies_along()) return
    call base%v_range(a, b)
    allocate (s%base_samples(2, 0:extent_intervals), s%normals(2, 0:extent_intervals), &
              s%sampled(0:extent_intervals))
    do i = 0, extent_intervals
      v = extent_sample_v(a, b, i)
      call base%evaluate(0.0_wp, v, 0, p, st)
      s%sampled(i) = st%ok()
      s%base_samples(:, i) = p%s(:, 0, 0)
      s%normals(:, i) = [-cos(v), -sin(v)]
    end do
  end function new_patch_section

  !> The window W over [e(1), e(4)] at x and its derivatives w(0:3);
  !> `inside` false outside (open) [e(1), e(4)], where W and all its
  !> derivatives are 0; `flat` true on [e(2), e(3)], where W is 1 and its
  !> derivatives 0 (the rising S is 1 there, the falling one 0: the same
  !> numbers without evaluating them).
  pure subroutine window(e, x, w, inside, flat)
    real(wp), intent(in) :: e(4), x
    real(wp), intent(out) :: w(0:3)
    logical, intent(out) :: inside, flat
    real(wp) :: rise(0:3), fall(0:3), p
    integer :: m
    w = 0
    inside = x > e(1) .and. x < e(4)
    flat = inside .and. x >= e(2) .and. x <= e(3)
    if (flat) w(0) = 1
    if (flat .or. .not. inside) return
    call smoothstep((x - e(1))/(e(2) - e(1)), rise, p)
    call smoothstep((x - e(3))/(e(4) - e(3)), fall, p)
    do m = 0, 3
      w(m) = rise(m)/(e(2) - e(1))**m - fall(m)/(e(4) - e(3))**m
    end do
  end subroutine window

  !> f and its partials f(i, j) = d^(i+j) f / du^i dv^j (i + j <= order,
  !> 0..3; the others 0) at (u, v), the sum over the patches (0 outside
  !> them); on_patch: whether (u, v) lies inside some patch's windows (else
  !> f is 0 without evaluating anything). Each partial has the same bits
  !> whatever the order asked.
  pure subroutine patch_offset_at(self, u, v, order, f, on_patch)
    class(patch_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    real(wp), intent(out) :: f(0:3, 0:3)
    logical, intent(out) :: on_patch
    real(wp) :: vv
    integer :: k
    logical :: wrapped, inside
    f = 0
    on_patch = .false.
    vv = v
    wrapped = .false.
    do k = 1, size(self%patches)
      if (.not. (u > self%patches(k)%u_ends(1) .and. u < self%patches(k)%u_ends(4))) cycle
      if (.not. wrapped) then   ! v into the base's range, once for all patches
        vv = base_v(self, v)
        wrapped = .true.
      end if
      call add_patch(self%patches(k), u, vv, order, f, inside)
      on_patch = on_patch .or. inside
    end do
  end subroutine patch_offset_at

  !> v in the base's range (wrapped where the base is periodic).
  pure real(wp) function base_v(self, v) result(vv)
    class(patch_section_t), intent(in) :: self
    real(wp), intent(in) :: v
    real(wp) :: v_min, v_max
    vv = v
    if (self%base%periodic()) then
      call self%base%v_range(v_min, v_max)
      vv = v_min + modulo(v - v_min, v_max - v_min)
    end if
  end function base_v

  !> f += patch's W(u) W(v) d(u, v) and its partials to `order` at (u, vv),
  !> vv in the base's range; inside: (u, vv) inside both windows (else f
  !> is left as it was).
  pure subroutine add_patch(patch, u, vv, order, f, inside)
    type(patch_offset_t), intent(in) :: patch
    real(wp), intent(in) :: u, vv
    integer, intent(in) :: order
    real(wp), intent(inout) :: f(0:3, 0:3)
    logical, intent(out) :: inside
    real(wp) :: wu(0:3), wv(0:3)
    type(spline_surface_eval_t) :: e
    type(status_t) :: st
    logical :: flat_u, flat_v
    call window(patch%u_ends, u, wu, inside, flat_u)
    if (.not. inside) return
    call window(patch%v_ends, vv, wv, inside, flat_v)
    if (.not. inside) return
    call patch%spline%evaluate(u, vv, e, st, order)   ! inside its domain
    call add_weighted(e, wu, wv, flat_u .and. flat_v, order, f)
  end subroutine add_patch

  !> f += W(u) W(v) d and its partials to `order` (Leibniz) from the
  !> spline's partials e and the windows wu, wv; where both windows are
  !> flat (W = 1, derivatives 0) the sum is the spline's partial alone (its
  !> other terms are zeros: the same number).
  pure subroutine add_weighted(e, wu, wv, flat, order, f)
    type(spline_surface_eval_t), intent(in) :: e
    real(wp), intent(in) :: wu(0:3), wv(0:3)
    logical, intent(in) :: flat
    integer, intent(in) :: order
    real(wp), intent(inout) :: f(0:3, 0:3)
    real(wp) :: d(0:3, 0:3)
    integer :: i, j, a, b
    d = 0
    d(0, 0) = e%f(1)
    d(1, 0) = e%fu(1); d(0, 1) = e%fv(1)
    d(2, 0) = e%fuu(1); d(1, 1) = e%fuv(1); d(0, 2) = e%fvv(1)
    d(3, 0) = e%fuuu(1); d(2, 1) = e%fuuv(1); d(1, 2) = e%fuvv(1); d(0, 3) = e%fvvv(1)
    if (flat) then
      do i = 0, order
        do j = 0, order - i
          f(i, j) = f(i, j) + d(i, j)
        end do
      end do
      return
    end if
    do i = 0, order
      do j = 0, order - i
        do a = 0, i
          do b = 0, j
            f(i, j) = f(i, j) + binom(a, i)*binom(b, j)*wu(a)*wv(b)*d(i - a, j - b)
          end do
        end do
      end do
    end do
  end subroutine add_weighted

  !> The base's point plus f n and its partials (Leibniz in v). Off the
  !> patches (or where f and its partials are 0) the base's point itself;
  !> on them, over a circle, cos v and sin v once for the circle and n.
  pure subroutine patch_evaluate(self, u, v, order, p, status)
    class(patch_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: f(0:3, 0:3), n(2, 0:3), c, s
    integer :: i, j, b
    logical :: on_patch
    call self%offset_at(u, v, order, f, on_patch)
    if (on_patch) on_patch = .not. all(f == 0)
    if (.not. on_patch) then
      call self%base%evaluate(u, v, order, p, status)
      return
    end if
    c = cos(v); s = sin(v)
    select type (base => self%base)
    type is (circle_section_t)
      call ellipse_point(base%radius, base%radius, c, s, order, p)   ! circle_evaluate's point
      status%code = STATUS_OK
    class default
      call base%evaluate(u, v, order, p, status)
      if (.not. status%ok()) return
    end select
    ! n = -[cos v, sin v] and its v-derivatives
    n(:, 0) = [-c, -s]; n(:, 1) = [s, -c]; n(:, 2) = [c, s]; n(:, 3) = [-s, c]
    do i = 0, order
      do j = 0, order - i
        do b = 0, j
          p%s(:, i, j) = p%s(:, i, j) + binom(b, j)*f(i, b)*n(:, j - b)
        end do
      end do
    end do
  end subroutine patch_evaluate

  !> The base's extent off the patches (a circle's radius without
  !> sampling); on a patch the largest distance of the points at the
  !> extent's samples of v, as any section's (geometry_cross_section's
  !> sampled_extent), and at least the base's. Over a base that does not vary
  !> along u the points are those patch_evaluate gives (base point + f n, the
  !> same operations) from the base's points and normals kept at
  !> construction: only f is evaluated at each sample, patch_offset_at's sum
  !> (add_weighted from each patch's windows) with each patch's spline on
  !> the samples in its window by one evaluate_grid (its shifts along u once
  !> per u, not at every sample; every partial the same bits as evaluate's).
  pure function patch_extent(self, u) result(r)
    class(patch_section_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: r
    real(wp) :: a, b, s(2), wu(0:3), wv(0:3, 0:extent_intervals), f(0:3, 0:3), f0(0:extent_intervals)
    real(wp) :: vv(0:extent_intervals)
    type(section_point_t) :: p
    type(spline_surface_eval_t) :: e(1, extent_intervals + 1)
    type(status_t) :: st
    integer :: i, k, m, n, at(extent_intervals + 1)
    logical :: on_patch(0:extent_intervals), inside, flat_u, flat_v(0:extent_intervals)
    r = self%base%extent(u)
    if (.not. any(self%patches%u_ends(1) < u .and. self%patches%u_ends(4) > u)) return
    call self%v_range(a, b)
    if (.not. allocated(self%base_samples)) then
      do i = 0, extent_intervals
        call self%evaluate(u, extent_sample_v(a, b, i), 0, p, st)
        if (st%ok()) r = max(r, norm2(p%s(:, 0, 0)))
      end do
      return
    end if
    do i = 0, extent_intervals
      vv(i) = base_v(self, extent_sample_v(a, b, i))
    end do
    ! patch_offset_at's f(0, 0) at every sample, patch by patch in its order
    f0 = 0
    on_patch = .false.
    do k = 1, size(self%patches)
      call window(self%patches(k)%u_ends, u, wu, inside, flat_u)
      if (.not. inside) cycle
      n = 0
      do i = 0, extent_intervals
        if (.not. self%sampled(i)) cycle
        call window(self%patches(k)%v_ends, vv(i), wv(:, i), inside, flat_v(i))
        if (.not. inside) cycle
        n = n + 1
        at(n) = i
      end do
      if (n == 0) cycle
      call self%patches(k)%spline%evaluate_grid([u], vv(at(:n)), e(:, :n), st)
      do m = 1, n
        i = at(m)
        f = 0
        f(0, 0) = f0(i)
        call add_weighted(e(1, m), wu, wv(:, i), flat_u .and. flat_v(i), 0, f)
        f0(i) = f(0, 0)
        on_patch(i) = .true.
      end do
    end do
    do i = 0, extent_intervals
      if (.not. self%sampled(i)) cycle
      s = self%base_samples(:, i)
      if (on_patch(i)) on_patch(i) = f0(i) /= 0   ! all of f: at order 0 only f(0, 0) is formed
      if (on_patch(i)) s = s + f0(i)*self%normals(:, i)
      r = max(r, norm2(s))
    end do
  end function patch_extent

  pure subroutine patch_range(self, v_min, v_max)
    class(patch_section_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    call self%base%v_range(v_min, v_max)
  end subroutine patch_range

  pure logical function patch_periodic(self) result(periodic)
    class(patch_section_t), intent(in) :: self
    periodic = self%base%periodic()
  end function patch_periodic

  pure function patch_parameter_unit(self) result(unit)
    class(patch_section_t), intent(in) :: self
    character(len=:), allocatable :: unit
    unit = self%base%parameter_unit()
  end function patch_parameter_unit
end module geometry_patch_section
