!> The rider's report quantities at any state between a ride's records
!> (rider_ride's extremes, numerics_dense_extremes): the probe, a copy of the
!> rider's mechanism (and, with may_fly, of its flight builds) that
!> evaluates the rider at the integrator's interpolated states.
module rider_probe
  use base_kinds, only: wp
  use base_vector, only: cross
  use base_status, only: status_t
  use geometry_slide_query, only: slide_surface_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use numerics_dense_extremes, only: dense_quantities_t
  use rider_extremes, only: extreme_quantities
  use rider_model, only: rider_layout_t, N_CONTACTS, CONTACT_PELVIS
  use rider_flight, only: set_holds, contact_gap
  implicit none (type, external)
  private
  public :: ride_probe_t, pelvis_state

  !> The rider's report quantities at any state between the records: a copy
  !> of the rider's mechanism (its closure warm starts are its own) with the
  !> water drag switched as at the record that starts the stretch and its
  !> closure started from that record's dependent coordinates (context: bit
  !> k-1 of context(1) set when contact k is in the water, then beta).
  type, extends(dense_quantities_t) :: ride_probe_t
    type(mechanism_t) :: mechanism
    type(mechanism_workspace_t) :: work
    !> with may_fly: the flight builds by their open contacts (the
    !> context's last number), their work arrays, and each build's
    !> coordinates in the full layout (rider_flight); the context's two
    !> numbers before it are the posture held in flight
    logical :: may_fly = .false.
    type(mechanism_t), pointer :: builds(:) => null()   ! the ride's own (models: never written)
    type(mechanism_workspace_t), allocatable :: works(:)
    integer, allocatable :: picks(:, :)
    type(rider_layout_t) :: layout
    class(slide_surface_t), allocatable :: slide
    real(wp) :: gravity(3) = 0            ! m/s^2
    real(wp), allocatable :: applied(:)   ! the context it was last switched to
  contains
    procedure :: evaluate => probe_evaluate
  end type ride_probe_t

contains

  !> Pelvis's speed, centre-of-mass acceleration, axes and the slide's
  !> reaction on the rider there, from a mechanism evaluated in work.
  subroutine pelvis_state(work, lay, speed, acceleration, axes, force, moment)
    type(mechanism_workspace_t), intent(in) :: work
    type(rider_layout_t), intent(in) :: lay
    real(wp), intent(out) :: speed, acceleration(3), axes(3, 3), force(3), moment(3)
    real(wp) :: s(3)
    associate (d => work%frames(lay%contact_frame(CONTACT_PELVIS)), p => work%frames(lay%body_frame(CONTACT_PELVIS)))
      ! the pelvis's speed: its contact point's, which in flight (the free
      ! chain, lay%lift > 0) is the pelvis frame's origin, not its foot point
      if (lay%lift > 0) then
        speed = norm2(p%v)
      else
        speed = norm2(d%v)
      end if
      s = matmul(p%rot, lay%body%pelvis%com)
      acceleration = p%a + cross(p%alpha, s) + cross(p%omega, cross(p%omega, s))
      axes = p%rot
      ! the slide's reaction on the rider at the pelvis contact is minus the
      ! load the mechanism puts on the Darboux frame there (docs/rider.md)
      force = -d%force
      moment = -d%torque
    end associate
  end subroutine pelvis_state

  !> The report quantities at (t, y) with the water drag of `context`.
  subroutine probe_evaluate(self, t, y, context, values, attached, status)
    class(ride_probe_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(in) :: context(:)
    real(wp), intent(out) :: values(:), attached(:, :)
    type(status_t), intent(inout) :: status
    real(wp) :: residual, speed, acceleration(3), axes(3, 3), force(3), moment(3)
    real(wp) :: angle(N_CONTACTS), distance(N_CONTACTS), normal(N_CONTACTS), gap(N_CONTACTS), gap_at(N_CONTACTS)
    integer :: f, k, mask, n_full
    mask = 0   ! the open contacts (without may_fly none)
    if (self%may_fly) then
      ! the full layout: the stretch's build at its own state
      mask = nint(context(size(context)))
      n_full = size(self%picks, 1)
      associate (m => self%builds(mask), pick => self%picks(:, mask))
        call evaluate_build(m, self%works(mask), [y(pick(1:m%f)), y(n_full + pick(1:m%f)), y(2*n_full + 1:)])
      end associate
      return
    end if
    call evaluate_build(self%mechanism, self%work, y)

  contains

    subroutine evaluate_build(m, work, y)
      type(mechanism_t), intent(in) :: m
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: y(:)
    associate (lay => self%layout)
      if (any(context /= self%applied)) then
        ! another stretch: its drag, and the closure from its record (a cold
        ! start: no predictor from the last solution, which may lie far off)
        call m%prepare_workspace(work)
        do k = 1, N_CONTACTS
          if (lay%drag(k) > 0) work%laws(lay%drag(k))%law%active = btest(nint(context(1)), k - 1)
        end do
        do k = 1, m%r
          work%scalars(m%beta(k))%q = context(1 + k)
        end do
        ! the posture held in flight
        if (self%may_fly) call set_holds(work, lay, nint(context(size(context))) /= 0, &
                                         context(size(context) - 2:size(context) - 1))
        work%warm = .false.
        work%converged = .false.
        self%applied = context
      end if
      f = m%f
      call m%evaluate(work, t, y(1:f), y(f + 1:2*f), residual, status)
      if (.not. status%ok()) return
      call pelvis_state(work, lay, speed, acceleration, axes, force, moment)
      do k = 1, N_CONTACTS
        call self%slide%wall_position(work%scalars(lay%u(k))%q, work%scalars(lay%v(k))%q, angle(k), distance(k), status)
        if (.not. status%ok()) return
        normal(k) = work%normal_force(lay%contact(k))
        gap(k) = 0
        gap_at(k) = 0
        if (.not. btest(mask, k - 1)) cycle
        gap(k) = contact_gap(work, lay, k)
        gap_at(k) = self%slide%arc_length(work%scalars(lay%u(k))%q)
      end do
      call extreme_quantities(speed, acceleration, axes, force, moment, &
        self%slide%arc_length(work%scalars(lay%u(CONTACT_PELVIS))%q), angle, distance, normal, self%gravity, &
        mask, gap, gap_at, values, attached)
    end associate
    end subroutine evaluate_build
  end subroutine probe_evaluate
end module rider_probe
