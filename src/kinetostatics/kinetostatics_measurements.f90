!> The four geometric measurements of thesis 3.2.2 between frames K_i and K_j,
!> as elements with a scalar output g (value, rates) whose generalized force is
!> the cut force lambda. Axes (plane normals, line directions) are unit vectors
!> given in the coordinates of their own frame; they turn with it, so
!> n' = omega x n and n'' = alpha x n + omega x (omega x n).
!>
!>   point-point (3.14):  g = d.d,            d = r_i - r_j
!>   plane-point (3.18):  g = n_i.(r_j - r_i)  (height of point j over the plane
!>                        through r_i with normal n_i; (3.18) with the sign chosen
!>                        so that g grows as the point moves along n_i)
!>   plane-plane (3.19):  g = n_i.n_j
!>   line-line  (3.20):   g = (e_i x e_j).(r_j - r_i)
!>
!> Forces (3.17 and "analogously" for II-IV): the transposed velocity map,
!> derived from g' written as omega_i.A + v_i.B + omega_j.C + v_j.D:
!>   plane-point: A = n x d, B = -n, C = 0, D = n
!>   plane-plane: A = n_i x n_j, C = n_j x n_i
!>   line-line:   A = e_i x (e_j x d), C = e_j x (d x e_i), B = -c, D = c (c = e_i x e_j)
!>
!> The coordinates of a point in a frame, g = R_i^T (r_j - r_i) (point_coordinates_t:
!> a contact point held at the origin of a Darboux frame, thesis (4.27)),
!> are the three plane-point measurements along the axes of K_i as one
!> element: the same operations on the same numbers, each axis as its own
!> plane-point measurement would do them (and the forces added in the order
!> of a backward pass over the three), with the shared differences formed once
!> and one call per pass instead of three.
module kinetostatics_measurements
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t
  implicit none (type, external)
  private
  public :: measurement_t, new_measurement, point_coordinates_t, new_point_coordinates
  public :: MEASURE_POINT_POINT, MEASURE_PLANE_POINT, MEASURE_PLANE_PLANE, MEASURE_LINE_LINE

  integer, parameter :: MEASURE_POINT_POINT = 1, MEASURE_PLANE_POINT = 2, &
                        MEASURE_PLANE_PLANE = 3, MEASURE_LINE_LINE = 4

  type, extends(element_t) :: measurement_t
    integer :: kind = MEASURE_POINT_POINT
    integer :: frame_i = 0, frame_j = 0, output = 0
    real(wp) :: axis_i(3) = [0, 0, 1], axis_j(3) = [0, 0, 1]   ! local unit vectors
    real(wp) :: ni(3) = 0, nj(3) = 0, d(3) = 0                 ! world, last position
  contains
    procedure :: position => m_position
    procedure :: velocity => m_velocity
    procedure :: acceleration => m_acceleration
    procedure :: force => m_force
    procedure :: links => m_links
  end type measurement_t

  !> g(k) = n_k.(r_j - r_i), n_k the k-th axis of K_i (module comment).
  type, extends(element_t) :: point_coordinates_t
    integer :: frame_i = 0, frame_j = 0, outputs(3) = 0
    real(wp) :: n(3, 3) = 0, d(3) = 0   ! world: the axes of K_i (columns), r_j - r_i; last position
  contains
    procedure :: position => pc_position
    procedure :: velocity => pc_velocity
    procedure :: acceleration => pc_acceleration
    procedure :: force => pc_force
    procedure :: links => pc_links
  end type point_coordinates_t

contains

  !> Links for kinetostatics_closure_blocks (element_links_t).
  pure subroutine m_links(self, links)
    class(measurement_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_i, self%frame_j], [integer ::], [integer ::], [self%output], relative=.true.)
  end subroutine m_links

  function new_measurement(name, kind, frame_i, frame_j, output, axis_i, axis_j) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: kind, frame_i, frame_j, output
    real(wp), intent(in), optional :: axis_i(3), axis_j(3)
    type(measurement_t) :: e
    e%name = name
    e%kind = kind
    e%frame_i = frame_i
    e%frame_j = frame_j
    e%output = output
    if (present(axis_i)) e%axis_i = axis_i/norm2(axis_i)
    if (present(axis_j)) e%axis_j = axis_j/norm2(axis_j)
  end function new_measurement

  pure subroutine m_position(self, frames, scalars, status)
    class(measurement_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    real(wp) :: g
    associate (unused_status => status)
    end associate
    associate (fi => frames(self%frame_i), fj => frames(self%frame_j))
      ! the axes each kind uses (point-point none, plane-point n_i)
      if (self%kind /= MEASURE_POINT_POINT) self%ni = matmul(fi%rot, self%axis_i)
      if (self%kind /= MEASURE_POINT_POINT .and. self%kind /= MEASURE_PLANE_POINT) &
        self%nj = matmul(fj%rot, self%axis_j)
      select case (self%kind)
      case (MEASURE_POINT_POINT)
        self%d = fi%r - fj%r
        g = dot_product(self%d, self%d)                          ! (3.14)
      case (MEASURE_PLANE_POINT)
        self%d = fj%r - fi%r
        g = dot_product(self%ni, self%d)                         ! (3.18)
      case (MEASURE_PLANE_PLANE)
        g = dot_product(self%ni, self%nj)                        ! (3.19)
      case default
        self%d = fj%r - fi%r
        g = dot_product(cross(self%ni, self%nj), self%d)         ! (3.20)
      end select
    end associate
    scalars(self%output)%q = g
  end subroutine m_position

  pure subroutine m_velocity(self, frames, scalars)
    class(measurement_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: gd, dni(3), dnj(3), dd(3)
    associate (fi => frames(self%frame_i), fj => frames(self%frame_j), ni => self%ni, nj => self%nj, &
               d => self%d)
      select case (self%kind)   ! each kind forms only the rates it needs (hot: closure Jacobians)
      case (MEASURE_POINT_POINT)
        gd = 2*dot_product(d, fi%v - fj%v)                      ! (3.15)
      case (MEASURE_PLANE_POINT)   ! a frame at rest turns no axis (closure Jacobian columns)
        dd = fj%v - fi%v
        if (any(fi%omega /= 0)) then
          dni = cross(fi%omega, ni)
          gd = dot_product(dni, d) + dot_product(ni, dd)
        else
          gd = dot_product(ni, dd)
        end if
      case (MEASURE_PLANE_PLANE)
        gd = 0
        if (any(fi%omega /= 0)) gd = dot_product(cross(fi%omega, ni), nj)
        if (any(fj%omega /= 0)) gd = gd + dot_product(ni, cross(fj%omega, nj))
      case default
        dni = cross(fi%omega, ni)
        dnj = cross(fj%omega, nj)
        dd = fj%v - fi%v
        gd = dot_product(cross(dni, nj) + cross(ni, dnj), d) + dot_product(cross(ni, nj), dd)
      end select
    end associate
    scalars(self%output)%qd = gd
  end subroutine m_velocity

  pure subroutine m_acceleration(self, frames, scalars)
    class(measurement_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: gdd, dni(3), dnj(3), ddni(3), ddnj(3), dd(3), ddd(3)
    logical :: turning_i, turning_j
    associate (fi => frames(self%frame_i), fj => frames(self%frame_j), ni => self%ni, nj => self%nj, &
               d => self%d)
      ! a frame at rest (mass-matrix columns) turns no axis: its products with
      ! omega are zero and skipped (the other terms summed in the same order)
      turning_i = any(fi%omega /= 0)
      turning_j = any(fj%omega /= 0)
      if (self%kind /= MEASURE_POINT_POINT) then
        dni = 0
        ddni = cross(fi%alpha, ni)
        if (turning_i) then
          dni = cross(fi%omega, ni)
          ddni = ddni + cross(fi%omega, dni)
        end if
      end if
      if (self%kind /= MEASURE_POINT_POINT .and. self%kind /= MEASURE_PLANE_POINT) then
        dnj = 0
        ddnj = cross(fj%alpha, nj)
        if (turning_j) then
          dnj = cross(fj%omega, nj)
          ddnj = ddnj + cross(fj%omega, dnj)
        end if
      end if
      select case (self%kind)
      case (MEASURE_POINT_POINT)
        dd = fi%v - fj%v
        gdd = 2*dot_product(d, fi%a - fj%a) + 2*dot_product(dd, dd)   ! (3.16)
      case (MEASURE_PLANE_POINT)
        ddd = fj%a - fi%a
        gdd = dot_product(ddni, d)
        if (turning_i) gdd = gdd + 2*dot_product(dni, fj%v - fi%v)
        gdd = gdd + dot_product(ni, ddd)
      case (MEASURE_PLANE_PLANE)
        gdd = dot_product(ddni, nj)
        if (turning_i .and. turning_j) gdd = gdd + 2*dot_product(dni, dnj)
        gdd = gdd + dot_product(ni, ddnj)
      case default
        dd = fj%v - fi%v
        ddd = fj%a - fi%a
        gdd = dot_product(cross(ddni, nj) + 2*cross(dni, dnj) + cross(ni, ddnj), d) &
              + 2*dot_product(cross(dni, nj) + cross(ni, dnj), dd) + dot_product(cross(ni, nj), ddd)
      end select
    end associate
    scalars(self%output)%qdd = gdd
  end subroutine m_acceleration

  pure subroutine m_force(self, frames, scalars, inertia, applied)
    class(measurement_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: lambda, ti(3), fi(3), tj(3), fj(3), c(3)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    lambda = scalars(self%output)%force
    if (lambda == 0) return   ! no cut force (the first pass of an inverse dynamics): nothing to add
    ti = 0; fi = 0; tj = 0; fj = 0
    associate (ni => self%ni, nj => self%nj, d => self%d)
      select case (self%kind)
      case (MEASURE_POINT_POINT)
        fi = 2*d*lambda                                        ! (3.17)
        fj = -fi
      case (MEASURE_PLANE_POINT)
        ti = cross(ni, d)*lambda
        fi = -ni*lambda
        fj = ni*lambda
      case (MEASURE_PLANE_PLANE)
        ti = cross(ni, nj)*lambda
        tj = -ti
      case default
        c = cross(ni, nj)
        ti = cross(ni, cross(nj, d))*lambda
        tj = cross(nj, cross(d, ni))*lambda
        fi = -c*lambda
        fj = c*lambda
      end select
    end associate
    frames(self%frame_i)%torque = frames(self%frame_i)%torque + ti
    frames(self%frame_i)%force = frames(self%frame_i)%force + fi
    frames(self%frame_j)%torque = frames(self%frame_j)%torque + tj
    frames(self%frame_j)%force = frames(self%frame_j)%force + fj
  end subroutine m_force

  ! ------------------------------------------------- the coordinates of a point

  !> The coordinates of the origin of K_j in K_i into the scalars `outputs`.
  function new_point_coordinates(name, frame_i, frame_j, outputs) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_i, frame_j, outputs(3)
    type(point_coordinates_t) :: e
    e%name = name
    e%frame_i = frame_i
    e%frame_j = frame_j
    e%outputs = outputs
  end function new_point_coordinates

  pure subroutine pc_links(self, links)
    class(point_coordinates_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_i, self%frame_j], [integer ::], [integer ::], self%outputs, &
                            relative=.true.)
  end subroutine pc_links

  pure subroutine pc_position(self, frames, scalars, status)
    class(point_coordinates_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    integer :: k
    associate (unused_status => status)
    end associate
    associate (fi => frames(self%frame_i), fj => frames(self%frame_j))
      self%n = fi%rot
      self%d = fj%r - fi%r
    end associate
    do k = 1, 3
      scalars(self%outputs(k))%q = dot_product(self%n(:, k), self%d)   ! (3.18)
    end do
  end subroutine pc_position

  pure subroutine pc_velocity(self, frames, scalars)
    class(point_coordinates_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: dd(3), dni(3)
    integer :: k
    associate (fi => frames(self%frame_i), fj => frames(self%frame_j), n => self%n, d => self%d)
      dd = fj%v - fi%v
      if (any(fi%omega /= 0)) then
        do k = 1, 3
          dni = cross(fi%omega, n(:, k))
          scalars(self%outputs(k))%qd = dot_product(dni, d) + dot_product(n(:, k), dd)
        end do
      else   ! a frame at rest turns no axis (closure Jacobian columns)
        do k = 1, 3
          scalars(self%outputs(k))%qd = dot_product(n(:, k), dd)
        end do
      end if
    end associate
  end subroutine pc_velocity

  pure subroutine pc_acceleration(self, frames, scalars)
    class(point_coordinates_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: gdd, dni(3), ddni(3), dd(3), ddd(3)
    integer :: k
    associate (fi => frames(self%frame_i), fj => frames(self%frame_j), n => self%n, d => self%d)
      ddd = fj%a - fi%a
      if (any(fi%omega /= 0)) then
        dd = fj%v - fi%v
        do k = 1, 3
          dni = cross(fi%omega, n(:, k))
          ddni = cross(fi%alpha, n(:, k)) + cross(fi%omega, dni)
          gdd = dot_product(ddni, d) + 2*dot_product(dni, dd)
          scalars(self%outputs(k))%qdd = gdd + dot_product(n(:, k), ddd)
        end do
      else   ! a frame at rest (mass-matrix columns): its products with omega are zero and skipped
        do k = 1, 3
          ddni = cross(fi%alpha, n(:, k))
          scalars(self%outputs(k))%qdd = dot_product(ddni, d) + dot_product(n(:, k), ddd)
        end do
      end if
    end associate
  end subroutine pc_acceleration

  pure subroutine pc_force(self, frames, scalars, inertia, applied)
    class(point_coordinates_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: lambda
    integer :: k
    associate (unused_i => inertia, unused_a => applied)
    end associate
    ! the axes backwards, as a backward pass over three plane-point measurements
    do k = 3, 1, -1
      lambda = scalars(self%outputs(k))%force
      if (lambda == 0) cycle   ! no cut force (the first pass of an inverse dynamics): nothing to add
      associate (fi => frames(self%frame_i), fj => frames(self%frame_j), n => self%n(:, k))
        fi%torque = fi%torque + cross(n, self%d)*lambda
        fi%force = fi%force + (-n*lambda)
        fj%torque = fj%torque + 0.0_wp
        fj%force = fj%force + n*lambda
      end associate
    end do
  end subroutine pc_force
end module kinetostatics_measurements
