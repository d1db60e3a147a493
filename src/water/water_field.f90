!> The water as a product: the computed water of one run, queried by the
!> centerline parameter u or by the centerline arc length, for the models
!> that read it (the rider, the design loop) without reaching into the
!> water's internals (docs/water.md, "The water field").
!>
!> Built from a completed run (its samples and their rates along the motion),
!> it holds, at the samples' u (strictly increasing: the run stops before the
!> water turns back), the values and the u-derivatives of
!>   time, arc length, v of the streamline, position, velocity, speed, height,
!>   width, and the axes x_M, z_M of K_M,
!> and, at the edges' own u, the v of the left and right edge with dv/du.
!> Every d/du is the model's d/dt divided by du/dt (the ODE's derivatives,
!> not differences), so each quantity is a piecewise cubic Hermite
!> interpolant: C1 in u, error O(h^4) in the node spacing h. Its accuracy
!> against the integrator's own dense output is measured in test_water_field
!> and stated in docs/water.md.
!>
!> Inlets (water_inlet): where one joined, the run recorded the water just
!> before and just after at the same u; both are nodes (the only nodes with
!> equal u), so the field jumps there: a query at u up to the inlet's u gets
!> the water before it (on the interval that ends there), a query at and
!> after it the merged water. The edge curves have no such pair (the edge
!> points lie up- and downstream of the streamline's u): across an inlet
!> they are interpolated between the last edge node before and the first
!> after (a few centimetres).
!>
!> The edges are curves on the surface: at the cross-section u, the left edge
!> lies at v_left(u) and the right one at v_right(u). They have their own nodes
!> (the edge points (u_e, v_e) solved at the samples, 4.25-4.26), so an edge is
!> known over its own range, which differs from the streamline's by a few
!> centimetres (the flow runs at an angle to the centerline).
!>
!> Queries are pure, allocation-free and read only the field (intent(in), no
!> cache): one field can be queried from several threads at once. A query
!> finds its node interval from a bucket table made with the field (one
!> bucket per node on average, then a short scan): the same interval as a
!> bisection, in a few comparisons instead of ~12. Outside the
!> computed range a query returns a location (before the start, after the end)
!> and no values: the field never extrapolates.
!>
!> K_M (thesis 4.2, the Darboux frame with sigma = 1, alpha_u = 0, alpha_v = 1):
!> x_M across the slide towards +v, z_M the surface normal into the tube,
!> y_M = z_M x x_M (about minus the direction of travel). The interpolated axes
!> are made orthonormal again at each query (their interpolation error is
!> O(h^4)).
module water_field
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_vector, only: cross
  use water_flow, only: water_series_t
  implicit none (type, external)
  private
  public :: water_field_t, water_at_t, water_edges_at_t, new_water_field, water_location_name
  public :: WATER_INSIDE, WATER_BEFORE_START, WATER_AFTER_END, WATER_NOT_COMPUTED

  !> Where a query lies with respect to the computed water.
  integer, parameter :: WATER_INSIDE = 0        !< inside the computed range: values filled
  integer, parameter :: WATER_BEFORE_START = 1  !< before the first sample (upstream of the inflow)
  integer, parameter :: WATER_AFTER_END = 2     !< after the last sample (the run's end or stop)
  integer, parameter :: WATER_NOT_COMPUTED = 3  !< no water there at all (empty field, no edges solved, a NaN query)

  ! rows of the node tables
  integer, parameter :: row_time = 1, row_arc = 2, row_v = 3, row_position = 4, row_velocity = 7, &
                        row_speed = 10, row_height = 11, row_width = 12, row_x_m = 13, row_z_m = 16, &
                        row_du = 19, row_dv = 20, n_rows = 20

  !> The water's edges at the cross-section u (surface parameters).
  type :: water_edges_at_t
    integer :: left_location = WATER_NOT_COMPUTED, right_location = WATER_NOT_COMPUTED
    real(wp) :: v_left = 0, v_right = 0            ! rad, left = towards +v
    real(wp) :: dv_left_du = 0, dv_right_du = 0    ! rad per unit of u
  end type water_edges_at_t

  !> The water at the cross-section u. Values are filled only where
  !> location = WATER_INSIDE.
  type :: water_at_t
    integer :: location = WATER_NOT_COMPUTED
    real(wp) :: u = 0                              ! surface parameter (m on slides, rad on a helix)
    real(wp) :: arc_length = 0                     ! m, centerline arc length from the slide's start
    real(wp) :: time = 0                           ! s, when the water point passes
    real(wp) :: v = 0, dv_du = 0                   ! rad, rad per unit of u: the streamline
    real(wp) :: du_dt = 0, dv_dt = 0               ! u-unit/s, rad/s: the surface rates of the water point
    real(wp) :: position(3) = 0                    ! m, streamline point
    real(wp) :: velocity(3) = 0                    ! m/s, water velocity (world)
    real(wp) :: speed = 0                          ! m/s
    real(wp) :: height = 0, width = 0              ! m, water height h and width b
    real(wp) :: area = 0                           ! m^2, Q/w (continuity)
    real(wp) :: flow_rate = 0                      ! m^3/s, Q here (the inlets upstream added)
    real(wp) :: beta = 0                           ! rad, flow angle to the centerline (+ towards +v)
    real(wp) :: x_m(3) = 0, y_m(3) = 0, z_m(3) = 0 ! K_M at the streamline point
    type(water_edges_at_t) :: edges
  end type water_at_t

  !> Where to start looking for x among increasing nodes: bucket b =
  !> int((x - first)*per_unit) + 1 covers [first + (b-1)/per_unit, first + b/per_unit),
  !> start(b) is the interval of its lower end.
  type :: node_index_t
    real(wp) :: first = 0, per_unit = 0
    integer, allocatable :: start(:)
  end type node_index_t

  type :: water_field_t
    private
    integer :: n = 0
    real(wp), allocatable :: u(:), arc(:)               ! nodes: u and their arc lengths (m)
    real(wp), allocatable :: node_flow(:)               ! m^3/s at the nodes (constant between inlets)
    real(wp), allocatable :: value(:, :), slope(:, :)   ! (n_rows, n): values and d/du
    real(wp), allocatable :: left(:, :), right(:, :)    ! (3, m): edge u, v, dv/du
    real(wp), allocatable :: left_u(:), right_u(:)      ! the edges' node u (contiguous for the search)
    type(node_index_t) :: u_index, arc_index, left_index, right_index
    real(wp) :: flow = 0                                ! m^3/s at the start
  contains
    procedure :: at_u => field_at_u
    procedure :: flow_at_u => field_flow_at_u
    procedure :: at_arc_length => field_at_arc_length
    procedure :: edges_at_u => field_edges_at_u
    procedure :: u_range => field_u_range
    procedure :: arc_length_range => field_arc_length_range
    procedure :: flow_rate => field_flow_rate
    procedure :: node_count => field_node_count
  end type water_field_t

contains

  pure function water_location_name(location) result(text)
    integer, intent(in) :: location
    character(len=:), allocatable :: text
    select case (location)
    case (WATER_INSIDE); text = 'inside the computed water'
    case (WATER_BEFORE_START); text = 'before the start of the water'
    case (WATER_AFTER_END); text = 'after the end of the computed water'
    case default; text = 'no water computed there'
    end select
  end function water_location_name

  !> The field of a completed run. Samples whose u does not increase (a record
  !> repeated at a stop) are left out, except the sample after an inlet joined
  !> (same u, more flow); edges only where they were solved: at
  !> the samples, or, given left and right (rows u, v, du/dt, dv/dt of edge
  !> points solved elsewhere, e.g. at the rows of the table), those instead.
  function new_water_field(series, status, left, right) result(field)
    type(water_series_t), intent(in) :: series
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: left(:, :), right(:, :)
    type(water_field_t) :: field
    integer :: i, k, n
    integer, allocatable :: keep(:)

    n = series%n
    if (n < 2) then
      call set_status(status, STATUS_INVALID_INPUT, 'water field: the run has fewer than two samples')
      return
    end if
    if (.not. allocated(series%centerline_speed)) then
      call set_status(status, STATUS_INVALID_INPUT, 'water field: the run kept no rates')
      return
    end if
    allocate (keep(n))
    k = 0
    do i = 1, n
      if (.not. series%du(i) > 0) cycle
      if (k > 0) then
        if (.not. (series%u(i) > series%u(keep(k)) .or. &
                   (series%u(i) == series%u(keep(k)) .and. series%flow(i) > series%flow(keep(k))))) cycle
      end if
      k = k + 1
      keep(k) = i
    end do
    ! a run stopped at once after an inlet joined: the merged water has no extent
    if (k >= 2) then
      if (series%u(keep(k)) == series%u(keep(k - 1))) k = k - 1
    end if
    if (k < 2) then
      call set_status(status, STATUS_INVALID_INPUT, 'water field: fewer than two samples with u increasing')
      return
    end if
    field%n = k
    field%flow = series%flow_rate
    allocate (field%u(k), field%arc(k), field%node_flow(k), field%value(n_rows, k), field%slope(n_rows, k))
    do k = 1, field%n
      i = keep(k)
      field%u(k) = series%u(i)
      field%node_flow(k) = series%flow(i)
      field%arc(k) = series%arc_length(i)
      field%value(:, k) = [series%time(i), series%arc_length(i), series%v(i), series%position(:, i), &
                           series%velocity(:, i), series%speed(i), series%height(i), series%width(i), &
                           series%x_m(:, i), series%z_m(:, i), series%du(i), series%dv(i)]
      field%slope(:, k) = [1.0_wp, series%centerline_speed(i)*series%du(i), series%dv(i), series%velocity(:, i), &
                           series%acceleration(:, i), series%speed_rate(i), series%height_rate(i), &
                           series%width_rate(i), series%x_m_rate(:, i), series%z_m_rate(:, i), series%udd(i), &
                           series%vdd(i)]/series%du(i)
    end do
    if (present(left) .and. present(right)) then
      call edge_nodes(left(1:2, :), left(3:4, :), [(1, i = 1, size(left, 2))], field%left)
      call edge_nodes(right(1:2, :), right(3:4, :), [(1, i = 1, size(right, 2))], field%right)
    else
      call edge_nodes(series%left_edge(:, :n), series%left_edge_rate(:, :n), series%edge_solved(:n), field%left)
      call edge_nodes(series%right_edge(:, :n), series%right_edge_rate(:, :n), series%edge_solved(:n), field%right)
    end if
    field%left_u = field%left(1, :)
    field%right_u = field%right(1, :)
    field%u_index = new_node_index(field%u)
    field%arc_index = new_node_index(field%arc)
    field%left_index = new_node_index(field%left_u)
    field%right_index = new_node_index(field%right_u)

  contains

    !> (u, v, dv/du) of the solved edge points whose u increases.
    subroutine edge_nodes(edge, rate, solved, nodes)
      real(wp), intent(in) :: edge(:, :), rate(:, :)
      integer, intent(in) :: solved(:)
      real(wp), allocatable, intent(out) :: nodes(:, :)
      integer :: j, m
      allocate (nodes(3, size(edge, 2)))
      m = 0
      do j = 1, size(edge, 2)
        if (solved(j) /= 1 .or. .not. rate(1, j) > 0) cycle
        if (m > 0) then
          if (.not. edge(1, j) > nodes(1, m)) cycle
        end if
        m = m + 1
        nodes(:, m) = [edge(1, j), edge(2, j), rate(2, j)/rate(1, j)]
      end do
      nodes = nodes(:, :m)
    end subroutine edge_nodes
  end function new_water_field

  !> The water at the cross-section u.
  pure subroutine field_at_u(self, u, water)
    class(water_field_t), intent(in) :: self
    real(wp), intent(in) :: u
    type(water_at_t), intent(out) :: water
    integer :: i
    if (self%n < 2) return   ! WATER_NOT_COMPUTED
    call locate(self%u, self%n, self%u_index, u, water%location, i)
    if (water%location /= WATER_INSIDE) return
    call evaluate(self, i, u, water)
  end subroutine field_at_u

  !> Only the flow at the cross-section u, for a drag law: the streamline
  !> point (m), the water velocity (m/s), the height (m) and the surface
  !> normal z_M, each the same numbers as at_u gives (no edges, no K_M's
  !> other axes, no flow angle). Values only where location = WATER_INSIDE.
  pure subroutine field_flow_at_u(self, u, location, position, velocity, height, z_m)
    class(water_field_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(out) :: location
    real(wp), intent(out) :: position(3), velocity(3), height, z_m(3)
    real(wp) :: val(row_position:row_height), der(row_position:row_height), zv(3), zd(3)
    integer :: i
    location = WATER_NOT_COMPUTED
    position = 0; velocity = 0; height = 0; z_m = 0
    if (self%n < 2) return
    call locate(self%u, self%n, self%u_index, u, location, i)
    if (location /= WATER_INSIDE) return
    call hermite_rows(self%u(i), self%u(i + 1), self%value(row_position:row_height, i), &
                      self%value(row_position:row_height, i + 1), self%slope(row_position:row_height, i), &
                      self%slope(row_position:row_height, i + 1), u, val, der)
    call hermite_rows(self%u(i), self%u(i + 1), self%value(row_z_m:row_z_m + 2, i), &
                      self%value(row_z_m:row_z_m + 2, i + 1), self%slope(row_z_m:row_z_m + 2, i), &
                      self%slope(row_z_m:row_z_m + 2, i + 1), u, zv, zd)
    position = val(row_position:row_position + 2)
    velocity = val(row_velocity:row_velocity + 2)
    height = val(row_height)
    z_m = zv/norm2(zv)
  end subroutine field_flow_at_u

  !> The water at centerline arc length s (m from the slide's start): u from
  !> the Hermite interpolant of u(s) (du/ds = 1/|c_u| at the nodes), then as at_u.
  pure subroutine field_at_arc_length(self, s, water)
    class(water_field_t), intent(in) :: self
    real(wp), intent(in) :: s
    type(water_at_t), intent(out) :: water
    real(wp) :: u, du_ds
    integer :: i
    if (self%n < 2) return   ! WATER_NOT_COMPUTED
    call locate(self%arc, self%n, self%arc_index, s, water%location, i)
    if (water%location /= WATER_INSIDE) return
    call hermite(self%arc(i), self%arc(i + 1), self%u(i), self%u(i + 1), 1/self%slope(row_arc, i), &
                 1/self%slope(row_arc, i + 1), s, u, du_ds)
    u = min(max(u, self%u(i)), self%u(i + 1))
    call evaluate(self, i, u, water)
  end subroutine field_at_arc_length

  !> Only the edges at u (for root functions on entering and leaving the water).
  pure subroutine field_edges_at_u(self, u, edges)
    class(water_field_t), intent(in) :: self
    real(wp), intent(in) :: u
    type(water_edges_at_t), intent(out) :: edges
    if (self%n < 2) return   ! WATER_NOT_COMPUTED
    call edge_at(self%left, self%left_u, self%left_index, u, edges%left_location, edges%v_left, edges%dv_left_du)
    call edge_at(self%right, self%right_u, self%right_index, u, edges%right_location, edges%v_right, &
                 edges%dv_right_du)
  end subroutine field_edges_at_u

  !> u of the first and the last node (0, 0 for an empty field).
  pure subroutine field_u_range(self, u_first, u_last)
    class(water_field_t), intent(in) :: self
    real(wp), intent(out) :: u_first, u_last
    u_first = 0; u_last = 0
    if (self%n < 2) return
    u_first = self%u(1); u_last = self%u(self%n)
  end subroutine field_u_range

  !> Arc length (m) of the first and the last node (0, 0 for an empty field).
  pure subroutine field_arc_length_range(self, s_first, s_last)
    class(water_field_t), intent(in) :: self
    real(wp), intent(out) :: s_first, s_last
    s_first = 0; s_last = 0
    if (self%n < 2) return
    s_first = self%arc(1); s_last = self%arc(self%n)
  end subroutine field_arc_length_range

  !> The flow rate at the start (m^3/s; inlets there added); along the
  !> slide: water_at_t%flow_rate.
  pure real(wp) function field_flow_rate(self) result(q)
    class(water_field_t), intent(in) :: self
    q = self%flow
  end function field_flow_rate

  pure integer function field_node_count(self) result(n)
    class(water_field_t), intent(in) :: self
    n = self%n
  end function field_node_count

  ! ------------------------------------------------------------ internals

  !> Everything at u in node interval i (u(i) <= u <= u(i+1)).
  pure subroutine evaluate(self, i, u, water)
    type(water_field_t), intent(in) :: self
    integer, intent(in) :: i
    real(wp), intent(in) :: u
    type(water_at_t), intent(inout) :: water
    real(wp) :: val(n_rows), der(n_rows), x(3), y(3), z(3)
    call hermite_rows(self%u(i), self%u(i + 1), self%value(:, i), self%value(:, i + 1), self%slope(:, i), &
                      self%slope(:, i + 1), u, val, der)
    water%u = u
    water%time = val(row_time)
    water%arc_length = val(row_arc)
    water%v = val(row_v); water%dv_du = der(row_v)
    water%du_dt = val(row_du); water%dv_dt = val(row_dv)
    water%position = val(row_position:row_position + 2)
    water%velocity = val(row_velocity:row_velocity + 2)
    water%speed = val(row_speed)
    water%height = val(row_height)
    water%width = val(row_width)
    water%flow_rate = self%node_flow(i)
    water%area = 0
    if (water%speed > 0) water%area = water%flow_rate/water%speed
    z = val(row_z_m:row_z_m + 2)
    z = z/norm2(z)
    x = val(row_x_m:row_x_m + 2)
    x = x - z*dot_product(z, x)
    x = x/norm2(x)
    y = cross(z, x)
    water%x_m = x; water%y_m = y; water%z_m = z
    water%beta = atan2(dot_product(x, water%velocity), -dot_product(y, water%velocity))
    call field_edges_at_u(self, u, water%edges)
  end subroutine evaluate

  !> The edge (nodes u, v, dv/du; node_u their first row) at u.
  pure subroutine edge_at(nodes, node_u, index, u, location, v, dv_du)
    real(wp), intent(in) :: nodes(:, :), node_u(:), u
    type(node_index_t), intent(in) :: index
    integer, intent(out) :: location
    real(wp), intent(out) :: v, dv_du
    integer :: i
    v = 0; dv_du = 0
    call locate(node_u, size(node_u), index, u, location, i)
    if (location /= WATER_INSIDE) return
    call hermite(nodes(1, i), nodes(1, i + 1), nodes(2, i), nodes(2, i + 1), nodes(3, i), nodes(3, i + 1), &
                 u, v, dv_du)
  end subroutine edge_at

  !> The bucket table of increasing nodes (empty for fewer than two nodes or
  !> no extent): one bucket per node.
  pure function new_node_index(nodes) result(index)
    real(wp), intent(in) :: nodes(:)
    type(node_index_t) :: index
    integer :: n, b, i
    n = size(nodes)
    allocate (index%start(0))
    if (n < 2) return
    if (.not. nodes(n) > nodes(1)) return
    index%first = nodes(1)
    index%per_unit = n/(nodes(n) - nodes(1))
    deallocate (index%start)
    allocate (index%start(n))
    i = 1
    do b = 1, n
      do while (i < n - 1)
        if (.not. nodes(i + 1) <= index%first + (b - 1)/index%per_unit) exit
        i = i + 1
      end do
      index%start(b) = i
    end do
  end function new_node_index

  !> Where x lies among the increasing nodes(1:n); if inside, the interval i
  !> with nodes(i) <= x <= nodes(i+1): the largest i <= n-1 with nodes(i) <= x,
  !> as a bisection finds it. The bucket's start is only a guess (rounding at
  !> a bucket's edge): the scans make it exact either way.
  pure subroutine locate(nodes, n, index, x, location, i)
    real(wp), intent(in) :: nodes(:), x
    integer, intent(in) :: n
    type(node_index_t), intent(in) :: index
    integer, intent(out) :: location, i
    integer :: b
    i = 1
    if (n < 2 .or. ieee_is_nan(x)) then   ! no comparison with a NaN (it traps in Debug builds)
      location = WATER_NOT_COMPUTED
    else if (x < nodes(1)) then
      location = WATER_BEFORE_START
    else if (x > nodes(n)) then
      location = WATER_AFTER_END
    else
      location = WATER_INSIDE
      if (size(index%start) > 0) then
        b = min(max(int((x - index%first)*index%per_unit) + 1, 1), size(index%start))
        i = index%start(b)
      end if
      do while (i > 1)
        if (nodes(i) <= x) exit
        i = i - 1
      end do
      do while (i < n - 1)
        if (nodes(i + 1) > x) exit
        i = i + 1
      end do
    end if
  end subroutine locate

  !> Cubic Hermite interpolation on [x0, x1] of values y and slopes m, and its derivative.
  pure subroutine hermite(x0, x1, y0, y1, m0, m1, x, y, dy)
    real(wp), intent(in) :: x0, x1, y0, y1, m0, m1, x
    real(wp), intent(out) :: y, dy
    real(wp) :: h, t, w(4), dw(4)
    h = x1 - x0
    t = (x - x0)/h
    call hermite_basis(t, w, dw)
    y = w(1)*y0 + w(2)*h*m0 + w(3)*y1 + w(4)*h*m1
    dy = (dw(1)*y0 + dw(3)*y1)/h + dw(2)*m0 + dw(4)*m1
  end subroutine hermite

  pure subroutine hermite_rows(x0, x1, y0, y1, m0, m1, x, y, dy)
    real(wp), intent(in) :: x0, x1, y0(:), y1(:), m0(:), m1(:), x
    real(wp), intent(out) :: y(:), dy(:)
    real(wp) :: h, t, w(4), dw(4)
    h = x1 - x0
    t = (x - x0)/h
    call hermite_basis(t, w, dw)
    y = w(1)*y0 + w(2)*h*m0 + w(3)*y1 + w(4)*h*m1
    dy = (dw(1)*y0 + dw(3)*y1)/h + dw(2)*m0 + dw(4)*m1
  end subroutine hermite_rows

  !> The cubic Hermite basis h00, h10, h01, h11 at t in [0, 1] and its t-derivatives.
  pure subroutine hermite_basis(t, w, dw)
    real(wp), intent(in) :: t
    real(wp), intent(out) :: w(4), dw(4)
    w = [(1 + 2*t)*(1 - t)**2, t*(1 - t)**2, t**2*(3 - 2*t), t**2*(t - 1)]
    dw = [6*t**2 - 6*t, 3*t**2 - 4*t + 1, 6*t - 6*t**2, 3*t**2 - 2*t]
  end subroutine hermite_basis
end module water_field
