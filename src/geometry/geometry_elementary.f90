!> The elementary surfaces of thesis 3.5.2.1 and the paraboloid with a
!> singular apex of thesis 3.5.1, with exact partial derivatives to third order.
!>
!> Each type has a public constructor of the type's own name that validates its
!> arguments and returns a status naming the offending value:
!>
!>     s = ellipsoid_t(a, b, c, status)
!>
!> Evaluation is valid for every real (u, v); the parameter box reported by
!> `domain` is what a simulation should stay in (or wrap, where periodic).
module geometry_elementary
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_INVALID_INPUT
  use base_constants, only: half_pi, two_pi
  use base_vector, only: cross
  use geometry_surface, only: surface_t, surface_point_t
  use base_text, only: format_real, format_vector
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none (type, external)
  private
  public :: plane_t, ellipsoid_t, paraboloid_t, elliptic_cylinder_t, apex_paraboloid_t

  !> |v| (rad) at which an ellipsoid's chart changes (surface_t's charts): 80
  !> degrees, so that after a change the point lies within 35 degrees of the
  !> new chart's equator (kinetostatics_inverse_surface_joint).
  real(wp), parameter :: pole_chart_limit = 1.4_wp
  real(wp), parameter :: cos_pole_chart_limit = cos(pole_chart_limit)

  !> Plane through A, B, C: r = r_A + u r_u + v r_v with unit r_u towards B and
  !> unit r_v towards C, thesis (3.55)-(3.56). u, v are lengths (m) along
  !> those (in general not orthogonal) directions.
  type, extends(surface_t) :: plane_t
    private
    real(wp) :: origin(3) = 0        ! r_A, m
    real(wp) :: e_u(3) = [1, 0, 0]   ! unit vector A -> B
    real(wp) :: e_v(3) = [0, 1, 0]   ! unit vector A -> C
  contains
    procedure :: evaluate => plane_evaluate
    procedure :: describe => plane_describe
    procedure :: parameter_units => plane_parameter_units
    procedure :: affine => plane_affine
  end type plane_t

  !> Ellipsoid r = [a cos v cos u, b cos v sin u, c sin v], thesis (3.57);
  !> u in [0, 2 pi] periodic, v in [-pi/2, pi/2] (r_u = 0 at the poles).
  type, extends(surface_t) :: ellipsoid_t
    private
    real(wp) :: a = 1, b = 1, c = 1  ! semi-axes, m
  contains
    procedure :: evaluate => ellipsoid_evaluate
    procedure :: domain => ellipsoid_domain
    procedure :: in_domain => ellipsoid_in_domain
    procedure :: periodic_u => ellipsoid_periodic_u
    procedure :: describe => ellipsoid_describe
    procedure :: parameter_units => ellipsoid_parameter_units
    procedure :: has_charts => ellipsoid_has_charts
    procedure :: chart_margin => ellipsoid_chart_margin
    procedure :: chart_toward => ellipsoid_chart_toward
    procedure :: chart => ellipsoid_pole_chart
    procedure :: chart_parameters => ellipsoid_chart_parameters
  end type ellipsoid_t

  !> Paraboloid r = [u, v, c u^2/a^2 + v^2/b^2], thesis (3.58), implemented
  !> literally: c multiplies only the u^2 term, so c = +1 gives the elliptic
  !> and c = -1 the hyperbolic paraboloid (a saddle). u, v in R (m).
  type, extends(surface_t) :: paraboloid_t
    private
    real(wp) :: a = 1, b = 1         ! m; curvatures 2/a^2 and 2/b^2 at the apex (1/m)
    real(wp) :: c = 1                ! +1 elliptic, -1 hyperbolic
  contains
    procedure :: evaluate => paraboloid_evaluate
    procedure :: describe => paraboloid_describe
    procedure :: parameter_units => paraboloid_parameter_units
  end type paraboloid_t

  !> Elliptic cylinder r = [a cos v, b sin v, u], thesis (3.59);
  !> u in R (m), v in [0, 2 pi] periodic.
  type, extends(surface_t) :: elliptic_cylinder_t
    private
    real(wp) :: a = 1, b = 1         ! semi-axes, m
  contains
    procedure :: evaluate => cylinder_evaluate
    procedure :: domain => cylinder_domain
    procedure :: periodic_v => cylinder_periodic_v
    procedure :: describe => cylinder_describe
    procedure :: parameter_units => cylinder_parameter_units
  end type elliptic_cylinder_t

  !> Paraboloid with a singular apex r = [a cos(u) v, b sin(u) v, v^2]
  !> (thesis 3.5.1); u in [0, 2 pi] periodic, v in R; r_u = 0 at v = 0.
  !> The same shape as paraboloid_t(a, b, +1): x^2/a^2 + y^2/b^2 = z.
  type, extends(surface_t) :: apex_paraboloid_t
    private
    real(wp) :: a = 1, b = 1         ! m (the shape z = x^2/a^2 + y^2/b^2; v in m)
  contains
    procedure :: evaluate => apex_evaluate
    procedure :: domain => apex_domain
    procedure :: periodic_u => apex_periodic_u
    procedure :: describe => apex_describe
    procedure :: parameter_units => apex_parameter_units
  end type apex_paraboloid_t

  interface plane_t
    module procedure new_plane
  end interface plane_t
  interface ellipsoid_t
    module procedure new_ellipsoid
  end interface ellipsoid_t
  interface paraboloid_t
    module procedure new_paraboloid
  end interface paraboloid_t
  interface elliptic_cylinder_t
    module procedure new_cylinder
  end interface elliptic_cylinder_t
  interface apex_paraboloid_t
    module procedure new_apex_paraboloid
  end interface apex_paraboloid_t

  !> Relative distance below which two of the plane's points count as coincident.
  real(wp), parameter :: coincident_tol = 1e-12_wp
  !> sin(angle) between A->B and A->C below which the points count as collinear.
  real(wp), parameter :: collinear_tol = 1e-10_wp

contains

  ! ---------------------------------------------------------------- constructors

  !> Plane through the points A, B, C (m), thesis (3.55)-(3.56). Fails if a
  !> point is not finite, two points coincide or the three are collinear.
  function new_plane(point_a, point_b, point_c, status) result(s)
    real(wp), intent(in) :: point_a(3), point_b(3), point_c(3)
    type(status_t), intent(out) :: status
    type(plane_t) :: s
    real(wp) :: ab(3), ac(3), scale
    if (.not. all(ieee_is_finite(point_a))) then
      call set_status(status, STATUS_INVALID_INPUT, 'plane: point A = ' // format_vector(point_a) // &
                      ' is not finite')
      return
    end if
    if (.not. all(ieee_is_finite(point_b))) then
      call set_status(status, STATUS_INVALID_INPUT, 'plane: point B = ' // format_vector(point_b) // &
                      ' is not finite')
      return
    end if
    if (.not. all(ieee_is_finite(point_c))) then
      call set_status(status, STATUS_INVALID_INPUT, 'plane: point C = ' // format_vector(point_c) // &
                      ' is not finite')
      return
    end if
    ab = point_b - point_a
    ac = point_c - point_a
    scale = max(norm2(point_a), norm2(point_b), norm2(point_c))
    if (norm2(ab) <= coincident_tol*scale) then
      call set_status(status, STATUS_INVALID_INPUT, 'plane: points A = ' // format_vector(point_a) // &
                      ' and B = ' // format_vector(point_b) // ' coincide; need three distinct points')
      return
    end if
    if (norm2(ac) <= coincident_tol*scale) then
      call set_status(status, STATUS_INVALID_INPUT, 'plane: points A = ' // format_vector(point_a) // &
                      ' and C = ' // format_vector(point_c) // ' coincide; need three distinct points')
      return
    end if
    s%origin = point_a
    s%e_u = ab/norm2(ab)
    s%e_v = ac/norm2(ac)
    if (norm2(cross(s%e_u, s%e_v)) <= collinear_tol) then
      call set_status(status, STATUS_INVALID_INPUT, 'plane: points A = ' // format_vector(point_a) // &
                      ', B = ' // format_vector(point_b) // ', C = ' // format_vector(point_c) // &
                      ' are collinear; they must span a plane')
      return
    end if
    status%code = STATUS_OK
  end function new_plane

  !> Ellipsoid with semi-axes a, b, c (m), thesis (3.57).
  function new_ellipsoid(a, b, c, status) result(s)
    real(wp), intent(in) :: a, b, c
    type(status_t), intent(out) :: status
    type(ellipsoid_t) :: s
    call check_positive('ellipsoid', 'a', a, status); if (.not. status%ok()) return
    call check_positive('ellipsoid', 'b', b, status); if (.not. status%ok()) return
    call check_positive('ellipsoid', 'c', c, status); if (.not. status%ok()) return
    s%a = a; s%b = b; s%c = c
  end function new_ellipsoid

  !> An ellipsoid has three charts of (3.57), one per axis its poles lie on.
  pure logical function ellipsoid_has_charts(self) result(has)
    class(ellipsoid_t), intent(in) :: self
    associate (unused => self)   ! every ellipsoid
    end associate
    has = .true.
  end function ellipsoid_has_charts

  !> cos v - cos(pole_chart_limit): positive inside the chart, zero at its edge.
  pure real(wp) function ellipsoid_chart_margin(self, v) result(margin)
    class(ellipsoid_t), intent(in) :: self
    real(wp), intent(in) :: v
    associate (unused => self)   ! the same edge for every ellipsoid
    end associate
    margin = cos(v) - cos_pole_chart_limit
  end function ellipsoid_chart_margin

  !> The axis (1, 2, 3: x, y, z) along which the point r lies least far out:
  !> the chart with its poles there has r farthest from them.
  pure integer function ellipsoid_chart_toward(self, r) result(k)
    class(ellipsoid_t), intent(in) :: self
    real(wp), intent(in) :: r(3)
    real(wp) :: abc(3)
    abc = [self%a, self%b, self%c]
    k = minloc(abs(r/abc), dim=1)
  end function ellipsoid_chart_toward

  !> The ellipsoid in another chart of (3.57): the one whose poles lie on
  !> its axis k (1, 2, 3: x, y, z; k = 3 is the ellipsoid itself). A point r'
  !> of the chart's surface `chart_surface` is the point r = P r' of this
  !> one, P the cyclic permutation taking the chart's z axis to axis k (a
  !> rotation: the outward normal stays outward).
  pure subroutine ellipsoid_pole_chart(self, k, chart_surface, p)
    class(ellipsoid_t), intent(in) :: self
    integer, intent(in) :: k
    class(surface_t), allocatable, intent(inout) :: chart_surface   ! replaced (pure: not intent(out))
    real(wp), intent(out) :: p(3, 3)
    type(ellipsoid_t) :: turned
    real(wp) :: abc(3)
    integer :: i1, i2
    abc = [self%a, self%b, self%c]
    i1 = modulo(k, 3) + 1
    i2 = modulo(k + 1, 3) + 1
    p = 0
    p(i1, 1) = 1
    p(i2, 2) = 1
    p(k, 3) = 1
    turned%a = abc(i1)
    turned%b = abc(i2)
    turned%c = abc(k)
    if (allocated(chart_surface)) deallocate (chart_surface)
    allocate (chart_surface, source=turned)
  end subroutine ellipsoid_pole_chart

  !> (u, v) of the point r of the ellipsoid, the inverse of (3.57). v by
  !> atan2, not asin(z/c): near a pole asin loses v to sqrt(2 eps) ~ 1e-8
  !> rad (a ball resting 1e-9 m off a ball's top was placed on the top).
  pure subroutine ellipsoid_chart_parameters(self, r, u, v, status)
    class(ellipsoid_t), intent(in) :: self
    real(wp), intent(in) :: r(3)
    real(wp), intent(out) :: u, v
    type(status_t), intent(out) :: status
    status%code = STATUS_OK
    v = atan2(r(3)/self%c, hypot(r(1)/self%a, r(2)/self%b))
    u = atan2(r(2)/self%b, r(1)/self%a)
  end subroutine ellipsoid_chart_parameters

  !> Paraboloid (3.58) with a, b > 0 (m) and c = +1 (elliptic) or -1 (hyperbolic).
  function new_paraboloid(a, b, c, status) result(s)
    real(wp), intent(in) :: a, b, c
    type(status_t), intent(out) :: status
    type(paraboloid_t) :: s
    call check_positive('paraboloid', 'a', a, status); if (.not. status%ok()) return
    call check_positive('paraboloid', 'b', b, status); if (.not. status%ok()) return
    if (c /= 1 .and. c /= -1) then
      call set_status(status, STATUS_INVALID_INPUT, 'paraboloid: c = ' // format_real(c) // &
                      ' is not allowed; use +1 (elliptic) or -1 (hyperbolic)')
      return
    end if
    s%a = a; s%b = b; s%c = c
  end function new_paraboloid

  !> Elliptic cylinder with semi-axes a, b (m), thesis (3.59).
  function new_cylinder(a, b, status) result(s)
    real(wp), intent(in) :: a, b
    type(status_t), intent(out) :: status
    type(elliptic_cylinder_t) :: s
    call check_positive('elliptic cylinder', 'a', a, status); if (.not. status%ok()) return
    call check_positive('elliptic cylinder', 'b', b, status); if (.not. status%ok()) return
    s%a = a; s%b = b
  end function new_cylinder

  !> Paraboloid with singular apex, a, b > 0 (m).
  function new_apex_paraboloid(a, b, status) result(s)
    real(wp), intent(in) :: a, b
    type(status_t), intent(out) :: status
    type(apex_paraboloid_t) :: s
    call check_positive('apex paraboloid', 'a', a, status); if (.not. status%ok()) return
    call check_positive('apex paraboloid', 'b', b, status); if (.not. status%ok()) return
    s%a = a; s%b = b
  end function new_apex_paraboloid

  pure subroutine check_positive(surface, name, x, status)
    character(len=*), intent(in) :: surface, name
    real(wp), intent(in) :: x
    type(status_t), intent(out) :: status
    if (.not. ieee_is_finite(x)) then
      call set_status(status, STATUS_INVALID_INPUT, surface // ': ' // name // ' = ' // &
                      format_real(x) // ' is not finite; it must be a finite length > 0 (m)')
    else if (x <= 0) then
      call set_status(status, STATUS_INVALID_INPUT, surface // ': ' // name // ' = ' // &
                      format_real(x) // ' is not allowed; it must be > 0 (m)')
    end if
  end subroutine check_positive

  ! ------------------------------------------------------------------ evaluation

  !> Common check of the requested order; sets p%order.
  pure subroutine start_evaluation(order, p, status)
    integer, intent(in) :: order
    type(surface_point_t), intent(inout) :: p
    type(status_t), intent(inout) :: status
    character(len=12) :: buffer
    if (order < 0 .or. order > 3) then
      write (buffer, '(i0)') order
      call set_status(status, STATUS_INVALID_INPUT, 'surface evaluation: order = ' // &
                      trim(buffer) // ' is not allowed; use 0..3')
      return
    end if
    p%order = order
  end subroutine start_evaluation

  !> thesis (3.55)-(3.56); all second and third partials vanish.
  pure subroutine plane_evaluate(self, u, v, order, p, status)
    class(plane_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    call start_evaluation(order, p, status); if (.not. status%ok()) return
    p%r = self%origin + u*self%e_u + v*self%e_v
    if (order >= 1) then
      p%ru = self%e_u
      p%rv = self%e_v
    end if
  end subroutine plane_evaluate

  !> thesis (3.57) and its partials.
  pure subroutine ellipsoid_evaluate(self, u, v, order, p, status)
    class(ellipsoid_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: cu, su, cv, sv
    call start_evaluation(order, p, status); if (.not. status%ok()) return
    associate (a => self%a, b => self%b, c => self%c)
      cu = cos(u); su = sin(u); cv = cos(v); sv = sin(v)
      p%r = [a*cv*cu, b*cv*su, c*sv]
      if (order >= 1) then
        p%ru = [-a*cv*su, b*cv*cu, 0.0_wp]
        p%rv = [-a*sv*cu, -b*sv*su, c*cv]
      end if
      if (order >= 2) then
        p%ruu = [-a*cv*cu, -b*cv*su, 0.0_wp]
        p%ruv = [a*sv*su, -b*sv*cu, 0.0_wp]
        p%rvv = [-a*cv*cu, -b*cv*su, -c*sv]
      end if
      if (order >= 3) then
        p%ruuu = [a*cv*su, -b*cv*cu, 0.0_wp]
        p%ruuv = [a*sv*cu, b*sv*su, 0.0_wp]
        p%ruvv = [a*cv*su, -b*cv*cu, 0.0_wp]
        p%rvvv = [a*sv*cu, b*sv*su, -c*cv]
      end if
    end associate
  end subroutine ellipsoid_evaluate

  !> thesis (3.58) and its partials; third partials vanish.
  pure subroutine paraboloid_evaluate(self, u, v, order, p, status)
    class(paraboloid_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: ka, kb
    call start_evaluation(order, p, status); if (.not. status%ok()) return
    ka = self%c/self%a**2
    kb = 1/self%b**2
    p%r = [u, v, ka*u**2 + kb*v**2]
    if (order >= 1) then
      p%ru = [1.0_wp, 0.0_wp, 2*ka*u]
      p%rv = [0.0_wp, 1.0_wp, 2*kb*v]
    end if
    if (order >= 2) then
      p%ruu = [0.0_wp, 0.0_wp, 2*ka]
      p%rvv = [0.0_wp, 0.0_wp, 2*kb]
    end if
  end subroutine paraboloid_evaluate

  !> thesis (3.59) and its partials.
  pure subroutine cylinder_evaluate(self, u, v, order, p, status)
    class(elliptic_cylinder_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: cv, sv
    call start_evaluation(order, p, status); if (.not. status%ok()) return
    cv = cos(v); sv = sin(v)
    p%r = [self%a*cv, self%b*sv, u]
    if (order >= 1) then
      p%ru = [0.0_wp, 0.0_wp, 1.0_wp]
      p%rv = [-self%a*sv, self%b*cv, 0.0_wp]
    end if
    if (order >= 2) p%rvv = [-self%a*cv, -self%b*sv, 0.0_wp]
    if (order >= 3) p%rvvv = [self%a*sv, -self%b*cv, 0.0_wp]
  end subroutine cylinder_evaluate

  !> r = [a cos(u) v, b sin(u) v, v^2] (thesis 3.5.1) and its partials.
  pure subroutine apex_evaluate(self, u, v, order, p, status)
    class(apex_paraboloid_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: cu, su
    call start_evaluation(order, p, status); if (.not. status%ok()) return
    associate (a => self%a, b => self%b)
      cu = cos(u); su = sin(u)
      p%r = [a*cu*v, b*su*v, v**2]
      if (order >= 1) then
        p%ru = [-a*su*v, b*cu*v, 0.0_wp]
        p%rv = [a*cu, b*su, 2*v]
      end if
      if (order >= 2) then
        p%ruu = [-a*cu*v, -b*su*v, 0.0_wp]
        p%ruv = [-a*su, b*cu, 0.0_wp]
        p%rvv = [0.0_wp, 0.0_wp, 2.0_wp]
      end if
      if (order >= 3) then
        p%ruuu = [a*su*v, -b*cu*v, 0.0_wp]
        p%ruuv = [-a*cu, -b*su, 0.0_wp]
      end if
    end associate
  end subroutine apex_evaluate

  ! ------------------------------------------------------- domains and names

  pure logical function ellipsoid_periodic_u(self) result(periodic)
    class(ellipsoid_t), intent(in) :: self
    associate (unused => self)   ! periodic for every instance of the type
    end associate
    periodic = .true.
  end function ellipsoid_periodic_u

  pure logical function cylinder_periodic_v(self) result(periodic)
    class(elliptic_cylinder_t), intent(in) :: self
    associate (unused => self)   ! periodic for every instance of the type
    end associate
    periodic = .true.
  end function cylinder_periodic_v

  pure logical function apex_periodic_u(self) result(periodic)
    class(apex_paraboloid_t), intent(in) :: self
    associate (unused => self)   ! periodic for every instance of the type
    end associate
    periodic = .true.
  end function apex_periodic_u

  !> The default test for this box and a periodic u, without its three calls
  !> (the inverse surface joint asks at every position).
  pure logical function ellipsoid_in_domain(self, u, v) result(inside)
    class(ellipsoid_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    associate (unused_self => self, unused_u => u)   ! the same box for every ellipsoid; u is periodic
    end associate
    inside = v >= -half_pi .and. v <= half_pi
  end function ellipsoid_in_domain

  pure subroutine ellipsoid_domain(self, u_min, u_max, v_min, v_max)
    class(ellipsoid_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    associate (unused => self)   ! the same box for every ellipsoid
    end associate
    u_min = 0; u_max = two_pi
    v_min = -half_pi; v_max = half_pi
  end subroutine ellipsoid_domain

  pure subroutine cylinder_domain(self, u_min, u_max, v_min, v_max)
    class(elliptic_cylinder_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    associate (unused => self)   ! the same box for every cylinder
    end associate
    u_min = -huge(1.0_wp); u_max = huge(1.0_wp)
    v_min = 0; v_max = two_pi
  end subroutine cylinder_domain

  pure subroutine apex_domain(self, u_min, u_max, v_min, v_max)
    class(apex_paraboloid_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    associate (unused => self)   ! the same box for every apex paraboloid
    end associate
    u_min = 0; u_max = two_pi
    v_min = -huge(1.0_wp); v_max = huge(1.0_wp)
  end subroutine apex_domain

  !> r = r_A + u e_u + v e_v: affine in (u, v).
  pure logical function plane_affine(self) result(affine)
    class(plane_t), intent(in) :: self
    associate (unused => self)
    end associate
    affine = .true.
  end function plane_affine

  pure function plane_describe(self) result(text)
    class(plane_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = 'plane through ' // format_vector(self%origin) // ' spanned by ' // format_vector(self%e_u) // &
           ' and ' // format_vector(self%e_v)
  end function plane_describe

  pure function ellipsoid_describe(self) result(text)
    class(ellipsoid_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = 'ellipsoid a = ' // format_real(self%a) // ' m, b = ' // format_real(self%b) // &
           ' m, c = ' // format_real(self%c) // ' m'
  end function ellipsoid_describe

  pure function paraboloid_describe(self) result(text)
    class(paraboloid_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (self%c > 0) then
      text = 'elliptic paraboloid'
    else
      text = 'hyperbolic paraboloid'
    end if
    text = text // ' a = ' // format_real(self%a) // ' m, b = ' // format_real(self%b) // ' m'
  end function paraboloid_describe

  pure function cylinder_describe(self) result(text)
    class(elliptic_cylinder_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = 'elliptic cylinder a = ' // format_real(self%a) // ' m, b = ' // format_real(self%b) // ' m'
  end function cylinder_describe

  pure function apex_describe(self) result(text)
    class(apex_paraboloid_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = 'paraboloid with singular apex a = ' // format_real(self%a) // ' m, b = ' // &
           format_real(self%b) // ' m'
  end function apex_describe


  pure subroutine plane_parameter_units(self, u_units, v_units)
    class(plane_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    associate (unused => self)
    end associate
    u_units = 'm'; v_units = 'm'
  end subroutine plane_parameter_units

  pure subroutine ellipsoid_parameter_units(self, u_units, v_units)
    class(ellipsoid_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    associate (unused => self)
    end associate
    u_units = 'rad'; v_units = 'rad'
  end subroutine ellipsoid_parameter_units

  pure subroutine paraboloid_parameter_units(self, u_units, v_units)
    class(paraboloid_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    associate (unused => self)
    end associate
    u_units = 'm'; v_units = 'm'
  end subroutine paraboloid_parameter_units

  pure subroutine cylinder_parameter_units(self, u_units, v_units)
    class(elliptic_cylinder_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    associate (unused => self)
    end associate
    u_units = 'm'; v_units = 'rad'
  end subroutine cylinder_parameter_units

  pure subroutine apex_parameter_units(self, u_units, v_units)
    class(apex_paraboloid_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    associate (unused => self)
    end associate
    u_units = 'rad'; v_units = 'm'
  end subroutine apex_parameter_units
end module geometry_elementary
