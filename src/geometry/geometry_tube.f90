!> Tube surfaces r(u, v) = c(u) + R_T(u) s(u, v) = c + y s_y + z s_z
!> (thesis 3.64, 3.66, appendix C.2): a cross-section s carried along a
!> centerline c by the horizon-vector frame of geometry_curve_frame.
!>
!> Partial derivatives to third order by Leibniz' rule,
!>   d^(i+j) r/du^i dv^j = [j = 0] c^(i) + sum_{a = y, z} sum_m C(i, m) a^(m) s_a^(i-m, j),
!> which is (C.17-C.25) for all i + j <= 3 (the printed C.22 has y_u for y_uu
!> in its third term, C.23 is r_uuv, and C.24 is r_uvv).
!> The parameter u is the centerline's; the arc length s(u) along the
!> centerline and its inverse are available (thesis 2.1). The tube answers
!> the slide query (geometry_slide_query): it carries a rider.
module geometry_tube
  use base_kinds, only: wp
  use base_text, only: format_short, format_vector, format_integer
  use base_status, only: status_t, set_status, prefix_status, STATUS_OK, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_point_t
  use geometry_slide_query, only: slide_surface_t, slide_slice_t, slide_bottom_v, general_wall_position, &
                                  general_bottom_radius
  use geometry_curve, only: curve_t, curve_point_t, line_curve_t, helix_curve_t, s_bend_curve_t, constant_curve_t
  use geometry_curve_frame, only: curve_frame_t, curve_frame_from_points
  use geometry_cross_section, only: cross_section_t, section_point_t, circle_section_t
  implicit none (type, external)
  private
  public :: tube_surface_t, new_tube_surface
  public :: new_straight_tube, new_helix_tube, new_s_bend_tube

  type, extends(slide_surface_t) :: tube_surface_t
    class(curve_t), allocatable :: centerline
    class(curve_t), allocatable :: horizon
    class(cross_section_t), allocatable :: section
    !> what it is, in words (describe): a slide from elements names them
    !> (geometry_slide_builder); unset: 'tube surface'
    character(len=:), allocatable :: name
  contains
    procedure :: evaluate => tube_evaluate
    procedure :: evaluate_with_centerline => tube_evaluate_with_centerline
    procedure :: points_on_grid => tube_points_on_grid
    procedure :: domain => tube_domain
    procedure :: periodic_v => tube_periodic_v
    procedure :: describe => tube_describe
    procedure :: parameter_units => tube_parameter_units
    procedure :: frame => tube_frame
    procedure :: arc_length => tube_arc_length
    procedure :: length => tube_length
    procedure :: parameter_at_length => tube_parameter_at_length
    procedure :: centerline_speed => tube_centerline_speed
    procedure :: centerline_point => tube_centerline_point
    procedure :: section_edges => tube_section_edges
    procedure :: wall_position => tube_wall_position
    procedure :: slice => tube_slice
    procedure :: evaluate_in_slice => tube_evaluate_in_slice
    procedure :: section_circle_radius => tube_section_circle_radius
    procedure :: section_varies => tube_section_varies
    procedure :: bottom_radius => tube_bottom_radius
    procedure :: built => tube_built
    procedure :: check => tube_check
  end type tube_surface_t

  real(wp), parameter :: pi_half = 1.5707963267948966_wp
  integer, parameter :: binom(0:3, 0:3) = reshape([1, 0, 0, 0, 1, 1, 0, 0, 1, 2, 1, 0, 1, 3, 3, 1], [4, 4])

contains

  !> A tube from its centerline, horizon field and cross-section. The horizon
  !> must be defined wherever the centerline is.
  function new_tube_surface(centerline, horizon, section, status) result(t)
    class(curve_t), intent(in) :: centerline, horizon
    class(cross_section_t), intent(in) :: section
    type(status_t), intent(out) :: status
    type(tube_surface_t) :: t
    real(wp) :: a, b, ha, hb
    call centerline%domain(a, b)
    call horizon%domain(ha, hb)
    if (.not. b > a) then
      call set_status(status, STATUS_INVALID_INPUT, 'tube surface: empty centerline domain')
      return
    end if
    if (ha > a .or. hb < b) then
      call set_status(status, STATUS_INVALID_INPUT, 'tube surface: the horizon field does not ' // &
                      'cover the centerline domain')
      return
    end if
    allocate (t%centerline, source=centerline)
    allocate (t%horizon, source=horizon)
    allocate (t%section, source=section)
  end function new_tube_surface

  ! ------------------------------------------------------------ closed-form tubes
  ! Circular tubes around closed-form centerlines with the horizon [0, 0, 1]
  ! (thesis 4.2: v = pi/2 at the bottom, v grows to the left): exact
  ! derivatives to every order the tube needs, arc length in closed form for
  ! the line and the helix.

  !> Straight tube of radius r falling at `incline` (rad) below the horizontal
  !> along +x: c = u [cos t, 0, -sin t], u in [0, length] (m, arc length).
  function new_straight_tube(radius, incline, length, status) result(t)
    real(wp), intent(in) :: radius, incline, length
    type(status_t), intent(out) :: status
    type(tube_surface_t) :: t
    t = new_tube_surface(line_curve_t(direction=[cos(incline), 0.0_wp, -sin(incline)], u_min=0.0_wp, &
                                      u_max=length), constant_curve_t(), circle_section_t(radius=radius), status)
  end function new_straight_tube

  !> Helical tube about the z-axis: c = [rho cos(s u), rho sin(s u), -p u],
  !> u in [0, u_max] (rad), p the descent per radian, s = +1 counter-clockwise
  !> seen from above, -1 clockwise.
  function new_helix_tube(radius, helix_radius, pitch, turn_sense, u_max, status) result(t)
    real(wp), intent(in) :: radius, helix_radius, pitch, turn_sense, u_max
    type(status_t), intent(out) :: status
    type(tube_surface_t) :: t
    t = new_tube_surface(helix_curve_t(radius=helix_radius, pitch=-pitch, turn=sign(1.0_wp, turn_sense), &
                                       u_min=0.0_wp, u_max=u_max), &
                         constant_curve_t(), circle_section_t(radius=radius), status)
  end function new_helix_tube

  !> S-bend tube c = [u, a sin(k u), -q u], u in [0, length] (m of x).
  function new_s_bend_tube(radius, amplitude, wavenumber, slope, length, status) result(t)
    real(wp), intent(in) :: radius, amplitude, wavenumber, slope, length
    type(status_t), intent(out) :: status
    type(tube_surface_t) :: t
    t = new_tube_surface(s_bend_curve_t(amplitude=amplitude, wavenumber=wavenumber, slope=slope, u_min=0.0_wp, &
                                        u_max=length), constant_curve_t(), circle_section_t(radius=radius), status)
  end function new_s_bend_tube

  pure subroutine tube_evaluate(self, u, v, order, p, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    type(slide_slice_t) :: slice
    call tube_slice(self, u, order, slice, status)
    if (.not. status%ok()) return
    call tube_evaluate_in_slice(self, slice, v, order, p, status)
  end subroutine tube_evaluate

  !> The surface point and, from the same evaluation, the centerline point c
  !> with its derivatives to order + 1 (for the curvature, without evaluating
  !> the centerline twice): the slice at u and the point in it.
  pure subroutine tube_evaluate_with_centerline(self, u, v, order, p, c, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(curve_point_t), intent(out) :: c
    type(status_t), intent(out) :: status
    type(slide_slice_t) :: slice
    call tube_slice(self, u, order, slice, status)
    if (.not. status%ok()) return
    c = slice%c
    call tube_evaluate_in_slice(self, slice, v, order, p, status)
  end subroutine tube_evaluate_with_centerline

  !> The tube at u: its centerline point to order + 1 and frame to `order`.
  pure subroutine tube_slice(self, u, order, slice, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(slide_slice_t), intent(out) :: slice
    type(status_t), intent(out) :: status
    type(curve_point_t) :: h
    if (order < 0 .or. order > 3) then
      call set_status(status, STATUS_INVALID_INPUT, 'tube surface: order must be 0..3')
      return
    end if
    slice%u = u
    slice%order = order
    call self%centerline%evaluate(u, order + 1, slice%c, status)
    if (.not. status%ok()) return
    call self%horizon%evaluate(u, order, h, status)
    if (.not. status%ok()) return
    call curve_frame_from_points(slice%c, h, order, slice%f, status, with_curvature=.false.)
    slice%kept = status%ok()
  end subroutine tube_slice

  !> The point at (slice%u, v) to `order` from the slice's centerline and
  !> frame (Leibniz in u, module comment); the order must be the slice's
  !> (the same bits as evaluate). A section that says it is one circle at
  !> every u (`circle_radius`, the shipped slides' tubes) takes
  !> circle_in_slice: the same numbers without the general section point.
  pure subroutine tube_evaluate_in_slice(self, slice, v, order, p, status)
    class(tube_surface_t), intent(in) :: self
    type(slide_slice_t), intent(in) :: slice
    real(wp), intent(in) :: v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: radius
    if (.not. (slice%kept .and. order == slice%order)) then
      call set_status(status, STATUS_INVALID_INPUT, 'tube surface: a point of order '//format_integer(order)// &
                      ' in a slice kept for order '//format_integer(slice%order))
      return
    end if
    radius = self%section%circle_radius()
    if (radius > 0) then
      call circle_in_slice(radius, slice%c, slice%f, v, order, p)
      status%code = STATUS_OK
    else
      call section_in_slice(self, slice, v, order, p, status)
    end if
  end subroutine tube_evaluate_in_slice

  !> tube_evaluate_in_slice for a circle of radius a: its section point
  !> s = [-a cos v, -a sin v] (thesis 4.2, the circle every `circle_radius`
  !> stands for) and v-partials (circle_section_t's evaluate's products)
  !> enter the sum of section_in_slice's constant section term by term, in
  !> the same order, so the bits are the same; no section point is built
  !> (its default initialisation, the test for u-derivatives, the array of
  !> terms: ~400 of ~560 instructions a point).
  pure subroutine circle_in_slice(a, c, f, v, order, p)
    real(wp), intent(in) :: a, v
    type(curve_point_t), intent(in) :: c
    type(curve_frame_t), intent(in) :: f
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    real(wp) :: cv, sv, sy(0:3), sz(0:3)
    cv = cos(v)
    sv = sin(v)
    sy(0) = -a*cv; sz(0) = -a*sv
    sy(1) = a*sv; sz(1) = -a*cv
    sy(2) = a*cv; sz(2) = a*sv
    sy(3) = -a*sv; sz(3) = a*cv
    p%order = order
    p%r = c%d(:, 0) + (f%y(:, 0)*sy(0) + f%z(:, 0)*sz(0))
    if (order >= 1) then
      p%ru = c%d(:, 1) + (f%y(:, 1)*sy(0) + f%z(:, 1)*sz(0))
      p%rv = f%y(:, 0)*sy(1) + f%z(:, 0)*sz(1)
    end if
    if (order >= 2) then
      p%ruu = c%d(:, 2) + (f%y(:, 2)*sy(0) + f%z(:, 2)*sz(0))
      p%ruv = f%y(:, 1)*sy(1) + f%z(:, 1)*sz(1)
      p%rvv = f%y(:, 0)*sy(2) + f%z(:, 0)*sz(2)
    end if
    if (order >= 3) then
      p%ruuu = c%d(:, 3) + (f%y(:, 3)*sy(0) + f%z(:, 3)*sz(0))
      p%ruuv = f%y(:, 2)*sy(1) + f%z(:, 2)*sz(1)
      p%ruvv = f%y(:, 1)*sy(2) + f%z(:, 1)*sz(2)
      p%rvvv = f%y(:, 0)*sy(3) + f%z(:, 0)*sz(3)
    end if
  end subroutine circle_in_slice

  !> tube_evaluate_in_slice for any section (Leibniz in u, module comment).
  pure subroutine section_in_slice(self, slice, v, order, p, status)
    class(tube_surface_t), intent(in) :: self
    type(slide_slice_t), intent(in) :: slice
    real(wp), intent(in) :: v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    type(section_point_t) :: s
    real(wp) :: t(3, 0:3, 0:3)   ! the section's part of d^(i+j) r/du^i dv^j (Leibniz in u)
    integer :: i, j, m
    associate (u => slice%u, c => slice%c, f => slice%f)
      call self%section%evaluate(u, v, order, s, status)
      if (.not. status%ok()) return
      ! a section that does not change along u (all but blended ones) leaves
      ! one term of the sum over m
      if (all(s%s(:, 1:order, 0:order - 1) == 0)) then
        do j = 0, order
          do i = 0, order - j
            t(:, i, j) = f%y(:, i)*s%s(1, 0, j) + f%z(:, i)*s%s(2, 0, j)
          end do
        end do
      else
        do j = 0, order
          do i = 0, order - j
            t(:, i, j) = 0
            do m = 0, i
              t(:, i, j) = t(:, i, j) + binom(m, i)*(f%y(:, m)*s%s(1, i - m, j) + f%z(:, m)*s%s(2, i - m, j))
            end do
          end do
        end do
      end if
      p%order = order
      p%r = c%d(:, 0) + t(:, 0, 0)
      if (order >= 1) then
        p%ru = c%d(:, 1) + t(:, 1, 0); p%rv = t(:, 0, 1)
      end if
      if (order >= 2) then
        p%ruu = c%d(:, 2) + t(:, 2, 0); p%ruv = t(:, 1, 1); p%rvv = t(:, 0, 2)
      end if
      if (order >= 3) then
        p%ruuu = c%d(:, 3) + t(:, 3, 0); p%ruuv = t(:, 2, 1); p%ruvv = t(:, 1, 2); p%rvvv = t(:, 0, 3)
      end if
    end associate
  end subroutine section_in_slice

  !> r = c + y s_y + z s_z on a grid: the centerline and its frame once per u.
  pure subroutine tube_points_on_grid(self, u, v, x, y, z, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u(:), v(:)
    real(wp), intent(out) :: x(:, :), y(:, :), z(:, :)   ! (size(v), size(u)), m
    type(status_t), intent(out) :: status
    type(curve_point_t) :: c, h
    type(curve_frame_t) :: f
    type(section_point_t) :: s
    real(wp) :: r(3)
    integer :: i, j
    do i = 1, size(u)
      call self%centerline%evaluate(u(i), 1, c, status)
      if (status%ok()) call self%horizon%evaluate(u(i), 0, h, status)
      if (status%ok()) call curve_frame_from_points(c, h, 0, f, status, with_curvature=.false.)
      if (.not. status%ok()) return
      do j = 1, size(v)
        call self%section%evaluate(u(i), v(j), 0, s, status)
        if (.not. status%ok()) return
        r = c%d(:, 0) + f%y(:, 0)*s%s(1, 0, 0) + f%z(:, 0)*s%s(2, 0, 0)
        x(j, i) = r(1); y(j, i) = r(2); z(j, i) = r(3)
      end do
    end do
  end subroutine tube_points_on_grid

  pure subroutine tube_domain(self, u_min, u_max, v_min, v_max)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    call self%centerline%domain(u_min, u_max)
    call self%section%v_range(v_min, v_max)
  end subroutine tube_domain

  pure logical function tube_periodic_v(self) result(periodic)
    class(tube_surface_t), intent(in) :: self
    periodic = self%section%periodic()
  end function tube_periodic_v

  pure function tube_describe(self) result(text)
    class(tube_surface_t), intent(in) :: self
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(f0.3)') self%centerline%total_length()
    if (allocated(self%name)) then
      text = self%name // ' (centerline length ' // trim(buf) // ' m)'
    else
      text = 'tube surface (centerline length ' // trim(buf) // ' m)'
    end if
  end function tube_describe

  !> The centerline frame at u with derivatives to `order`, chi and chi_u.
  pure subroutine tube_frame(self, u, order, f, status, c)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_frame_t), intent(out) :: f
    type(status_t), intent(out) :: status
    type(curve_point_t), intent(out), optional :: c
    type(curve_point_t) :: cp, hp
    call self%centerline%evaluate(u, order + 1, cp, status)
    if (.not. status%ok()) return
    call self%horizon%evaluate(u, order, hp, status)
    if (.not. status%ok()) return
    call curve_frame_from_points(cp, hp, order, f, status)
    if (present(c)) c = cp
  end subroutine tube_frame

  !> Arc length of the centerline from its start to u, m.
  pure real(wp) function tube_arc_length(self, u) result(s)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: a, b
    call self%centerline%domain(a, b)
    s = self%centerline%arc_length(a, u)
  end function tube_arc_length

  !> Length of the whole centerline, m.
  pure real(wp) function tube_length(self) result(s)
    class(tube_surface_t), intent(in) :: self
    s = self%centerline%total_length()
  end function tube_length

  !> u at arc length s (m) from the start of the centerline.
  pure subroutine tube_parameter_at_length(self, s, u, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: s
    real(wp), intent(out) :: u
    type(status_t), intent(out) :: status
    call self%centerline%parameter_at_length(s, u, status)
  end subroutine tube_parameter_at_length

  !> Checks the whole tube before it is used, at n_samples values of u: the
  !> frame exists (horizon not parallel to the tangent) and the centerline's
  !> radius of curvature 1/chi stays above the section's extent (else the tube
  !> folds onto itself). The message says where (u, arc length, point). A
  !> section that does not change along u has one extent, taken once.
  subroutine tube_check(self, n_samples, status)
    class(tube_surface_t), intent(in) :: self
    integer, intent(in) :: n_samples
    type(status_t), intent(inout) :: status
    real(wp) :: a, b, u, extent, worst_ratio, worst_u, worst_chi, worst_extent, fixed
    type(curve_frame_t) :: f
    type(curve_point_t) :: c
    type(status_t) :: st
    integer :: i
    character(len=300) :: buf
    call self%centerline%domain(a, b)
    fixed = fixed_extent(self, a)
    worst_ratio = 0; worst_u = a; worst_chi = 0; worst_extent = 0
    do i = 0, n_samples - 1
      u = a + (b - a)*i/real(max(n_samples - 1, 1), wp)
      call self%frame(u, 1, f, st, c)
      if (.not. st%ok()) then
        buf = ' at u = ' // format_short(u) // ' (arc length ' // format_short(self%arc_length(u)) // ' m, point [' // &
              format_short(c%d(1, 0)) // ', ' // format_short(c%d(2, 0)) // ', ' // format_short(c%d(3, 0)) // '] m)'
        status = st
        call prefix_status(status, 'tube surface' // trim(buf))
        return
      end if
      extent = fixed
      if (extent < 0) extent = self%section%extent(u)
      if (f%chi*extent > worst_ratio) then
        worst_ratio = f%chi*extent; worst_u = u; worst_chi = f%chi; worst_extent = extent
      end if
    end do
    if (worst_ratio >= 1) then
      call self%centerline%evaluate(worst_u, 0, c, st)
      buf = 'radius of curvature ' // format_short(1/worst_chi) // ' m below the cross-section extent ' // &
            format_short(worst_extent) // ' m at u = ' // format_short(worst_u) // ' (arc length ' // &
            format_short(self%arc_length(worst_u)) // ' m, point ' // format_vector(c%d(:, 0)) // &
            ' m): the tube would fold onto itself'
      call set_status(status, STATUS_INVALID_INPUT, 'tube surface: ' // trim(buf))
      return
    end if
    call tube_check_clearance(self, fixed, status)
  end subroutine tube_check

  !> The section's extent if it is one at every u (a kind that does not vary
  !> along u: the same number as extent(u) at any u), else -1.
  pure real(wp) function fixed_extent(self, u) result(extent)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    extent = -1
    if (.not. self%section%varies_along()) extent = self%section%extent(u)
  end function fixed_extent

  !> u is the centerline's parameter, v the cross-section's.
  pure subroutine tube_parameter_units(self, u_units, v_units)
    class(tube_surface_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    u_units = self%centerline%parameter_unit()
    v_units = self%section%parameter_unit()
  end subroutine tube_parameter_units

  !> ds/du = |c_u| at u, from the centerline's derivative.
  pure subroutine tube_centerline_speed(self, u, speed, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: speed
    type(status_t), intent(out) :: status
    type(curve_point_t) :: c
    speed = 0
    call self%centerline%evaluate(u, 1, c, status)
    if (status%ok()) speed = norm2(c%d(:, 1))
  end subroutine tube_centerline_speed

  !> c(u) and its derivatives to `order`: the centerline's own evaluation.
  pure subroutine tube_centerline_point(self, u, order, c, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: c
    type(status_t), intent(out) :: status
    call self%centerline%evaluate(u, order, c, status)
  end subroutine tube_centerline_point

  !> The section's v range (-huge, huge where it is closed).
  pure subroutine tube_section_edges(self, u, v_min, v_max)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: v_min, v_max
    associate (unused => u)
    end associate
    if (self%section%periodic()) then
      v_min = -huge(1.0_wp); v_max = huge(1.0_wp)
    else
      call self%section%v_range(v_min, v_max)
    end if
  end subroutine tube_section_edges

  !> On a circular section the wall position is closed-form: the normal is
  !> radial, so the angle is v - pi/2 and the distance r (v - pi/2); other
  !> sections take the general quadrature.
  subroutine tube_wall_position(self, u, v, angle, distance, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    real(wp), intent(out) :: angle, distance
    type(status_t), intent(inout) :: status
    real(wp) :: radius
    radius = self%section%circle_radius()
    if (radius > 0) then
      angle = v - slide_bottom_v
      distance = radius*angle
    else
      call general_wall_position(self, u, v, angle, distance, status)
    end if
  end subroutine tube_wall_position

  !> The section's circle radius (0: not a circle), from the section.
  pure real(wp) function tube_section_circle_radius(self) result(radius)
    class(tube_surface_t), intent(in) :: self
    radius = self%section%circle_radius()
  end function tube_section_circle_radius

  pure logical function tube_section_varies(self) result(varies)
    class(tube_surface_t), intent(in) :: self
    varies = self%section%varies_along()
  end function tube_section_varies

  !> A tube is built with its centerline (a default tube_surface_t is not).
  pure logical function tube_built(self) result(built)
    class(tube_surface_t), intent(in) :: self
    built = allocated(self%centerline) .and. allocated(self%horizon) .and. allocated(self%section)
  end function tube_built

  !> A circle's radius is its bottom's everywhere (and that of any arc of
  !> the tube's surface across it: the circle is a line of curvature);
  !> other sections: the general sampling.
  subroutine tube_bottom_radius(self, radius, u_at, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(out) :: radius, u_at
    type(status_t), intent(inout) :: status
    real(wp) :: v_min, v_max, u_max
    radius = self%section%circle_radius()
    if (radius > 0) then
      call self%domain(u_at, u_max, v_min, v_max)
    else
      call general_bottom_radius(self, radius, u_at, status)
    end if
  end subroutine tube_bottom_radius

  !> No part of the tube passes through another (the fold check above is
  !> local): centerline points far apart along the tube, by more than
  !> pi/2 (e_i + e_j) of arc length (e the cross-section extent), must lie
  !> farther apart in space than e_i + e_j. Points that near along a curve
  !> whose radius of curvature exceeds the extent (what the fold check
  !> ensures) are always that far apart, so only a tube that comes back to
  !> itself (a flat helix, a loop) fails. Samples every quarter of the
  !> smallest extent (at most max_samples): an overlap deeper than about
  !> that spacing is found. fixed: the section's extent at every u
  !> (fixed_extent; < 0: taken at each u).
  subroutine tube_check_clearance(self, fixed, status)
    class(tube_surface_t), intent(in) :: self
    real(wp), intent(in) :: fixed
    type(status_t), intent(inout) :: status
    integer, parameter :: max_samples = 4000
    real(wp), allocatable :: u(:), s(:), e(:), p(:, :), f(:, :)
    real(wp) :: a, b, smallest, d, step, e_max, spacings
    type(curve_point_t) :: c
    type(status_t) :: st
    integer :: n, i, j
    call self%centerline%domain(a, b)
    smallest = min(huge(1.0_wp), fixed)
    if (fixed < 0) then
      smallest = huge(1.0_wp)
      do i = 0, 100
        smallest = min(smallest, self%section%extent(a + (b - a)*i/100.0_wp))
      end do
    end if
    if (.not. smallest > 0) return
    ! the count in reals first: a wild spline (1e8 m from points 5 km apart)
    ! would overflow the integer (a trap in Debug, a garbage count in Release)
    spacings = 4*self%length()/smallest
    if (spacings < max_samples) then
      n = max(100, min(max_samples, ceiling(spacings) + 1))
    else
      n = max_samples
    end if
    allocate (u(n), s(n), e(n), p(3, n), f(2, n))
    do i = 1, n
      u(i) = a + (b - a)*(i - 1)/real(n - 1, wp)
      call self%centerline%evaluate(u(i), 2, c, st)
      if (.not. st%ok()) return   ! reported by the frame check
      p(:, i) = c%d(:, 0)
      e(i) = fixed
      if (fixed < 0) e(i) = self%section%extent(u(i))
      f(:, i) = [norm2(c%d(:, 1)), dot_product(c%d(:, 1), c%d(:, 2))/norm2(c%d(:, 1))]   ! |c_u| and its rate
      if (i == 1) then
        s(i) = 0
      else   ! arc length by the trapezoid of |c_u| with its end slopes (error h^5 |c_u|''''/720)
        s(i) = s(i - 1) + (u(i) - u(i - 1))*(f(1, i - 1) + f(1, i))/2 + (u(i) - u(i - 1))**2*(f(2, i - 1) - f(2, i))/12
      end if
    end do
    ! consecutive samples lie at most `step` apart in space, so a point at
    ! distance d from p(i) has no later sample within d - k step of p(i) for k
    ! samples on: the search skips those (every pair it leaves out is farther
    ! apart than 2 e_max, the largest sum of extents)
    step = 0
    do i = 2, n
      step = max(step, norm2(p(:, i) - p(:, i - 1)))
    end do
    e_max = maxval(e)
    do i = 1, n
      j = i + 1
      do while (j <= n)
        if (s(j) - s(i) <= pi_half*(e(i) + e(j))) then
          j = j + 1
          cycle
        end if
        d = norm2(p(:, j) - p(:, i))
        if (d >= (e(i) + e(j))*(1 - 1e-9_wp)) then
          j = j + max(1, int((d - 2*e_max)/max(step, tiny(1.0_wp))))
          cycle
        end if
        call set_status(status, STATUS_INVALID_INPUT, 'tube surface: the tube passes through itself: the '// &
                        'centerline at arc length '//format_short(s(i))//' m (point '//short_point(p(:, i))// &
                        ') and at '//format_short(s(j))//' m (point '//short_point(p(:, j))//') is '// &
                        format_short(d)//' m apart, less than the cross-section extents '// &
                        format_short(e(i))//' + '//format_short(e(j))//' m')
        return
      end do
    end do
  end subroutine tube_check_clearance

  pure function short_point(x) result(text)
    real(wp), intent(in) :: x(3)
    character(len=:), allocatable :: text
    text = '['//format_short(x(1))//', '//format_short(x(2))//', '//format_short(x(3))//']'
  end function short_point
end module geometry_tube
