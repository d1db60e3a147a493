!> The mechanism (the model) apart from the workspace of its computations
!> (kinetostatics_mechanism_workspace), with the sled of kinetostatics_models
!> in a paraboloid bowl with Coulomb friction: a closed loop (the closure's
!> warm start), contacts and friction scaled by N (the block system):
!> - the cached dynamics is the workspace's: one mechanism evaluated at A
!>   with workspace 1, at B with workspace 2, then at A with workspace 1
!>   again is reused, bit for bit (workspace 1 still holds A's state: the
!>   mechanism holds none; on the old code it held B's and was recomputed);
!>   at A twice with workspace 1 it is reused, bit for bit;
!> - the results are the workspace's: workspace 1 keeps A's accelerations,
!>   normal forces and friction forces (the laws' loads and factors) while
!>   workspace 2 computes B's;
!> - two integrations of copies of one mechanism, each ODE object with its
!>   own workspace, advanced in turns, give bit for bit the results of one
!>   integration alone (nothing shared between them);
!> - two integrations of ONE mechanism object (two ODE objects pointing to
!>   it, each with its own workspace), advanced in turns, give bit for bit
!>   the results of each alone: the mechanism holds no state of an
!>   integration (on the old code the frames, scalars, laws and the
!>   closure's warm start were the mechanism's: each run's closure started
!>   from the other's solution).
!> An ODE object that integrates a mechanism it does not own (a pointer to
!> it) with a workspace of its own: y = [q, s], y' = [q', s'] from the
!> mechanism's dynamics. Two of them can integrate one mechanism object.
module shared_mechanism_ode
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_system_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  implicit none (type, external)
  private
  public :: shared_ode_t

  type, extends(ode_system_t) :: shared_ode_t
    type(mechanism_t), pointer :: mechanism => null()
    type(mechanism_workspace_t) :: work
  contains
    procedure :: rhs => shared_rhs
  end type shared_ode_t

contains

  subroutine shared_rhs(self, t, y, ydot, status)
    class(shared_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    integer :: f, n
    f = self%mechanism%f
    n = f + self%mechanism%ns
    call self%mechanism%dynamics(self%work, t, y(1:f), y(f + 1:n), ydot(f + 1:n), status)
    if (status%ok()) ydot(1:f) = self%work%rates
  end subroutine shared_rhs
end module shared_mechanism_ode

program test_mechanism_workspace
  use base_kinds, only: wp
  use base_status, only: status_t
  use testing, only: check, finish_tests
  use geometry_surface, only: surface_t
  use geometry_elementary, only: paraboloid_t
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: sled_params_t, build_sled
  use kinetostatics_force_law_factory, only: law_spec
  use shared_mechanism_ode, only: shared_ode_t
  implicit none (type, external)

  real(wp), parameter :: q_a(3) = [1.0_wp, 0.0_wp, 0.3_wp], s_a(3) = [0.0_wp, 1.2_wp, 0.5_wp]
  real(wp), parameter :: q_b(3) = [0.8_wp, 0.3_wp, -0.2_wp], s_b(3) = [0.4_wp, -0.9_wp, 0.1_wp]
  integer, parameter :: n_out = 20        ! output times of the integrations ...
  real(wp), parameter :: dt = 0.05_wp      ! ... this far apart (s)
  type(mechanism_t), target :: sled

  call build(sled)
  call cache_belongs_to_the_mechanism_state()
  call interleaved_integrations()
  call one_mechanism_two_integrations()
  call finish_tests('test_mechanism_workspace')

contains

  subroutine build(m)
    type(mechanism_t), intent(out) :: m
    type(sled_params_t) :: p
    class(surface_t), allocatable :: surface
    type(status_t) :: st
    surface = paraboloid_t(2.0_wp, 2.5_wp, 1.0_wp, st)
    p%friction = [law_spec('coulomb', 'mu', 0.3_wp)]
    call build_sled(p, surface, q_a, m, st)
    call check(st%ok(), 'the sled in the bowl builds: '//st%text())
  end subroutine build

  subroutine cache_belongs_to_the_mechanism_state()
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work_1, work_2
    type(status_t) :: st
    real(wp) :: a(3), again(3), b(3), normal_a(2), friction_a(3)
    integer :: reused
    m = sled
    call m%check_start(work_1, q_a, st)
    call check(st%ok(), 'workspace: the sled starts: '//st%text())
    call m%dynamics(work_1, 0.0_wp, q_a, s_a, a, st)
    normal_a = work_1%normal
    friction_a = m%law_force(work_1, 1)
    reused = work_1%dynamics_reused
    call m%dynamics(work_1, 0.0_wp, q_a, s_a, again, st)
    call check(st%ok() .and. work_1%dynamics_reused == reused + 1 .and. all(again == a) .and. &
               all(work_1%normal == normal_a), 'workspace: the same state again with the same workspace: reused, '// &
               'the same results bit for bit')
    call m%dynamics(work_2, 0.0_wp, q_b, s_b, b, st)
    call check(st%ok() .and. maxval(abs(b - a)) > 1e-3_wp*maxval(abs(a)), &
               'workspace: another state with another workspace: other accelerations')
    call check(all(work_1%normal == normal_a) .and. all(work_1%qdd == a) .and. all(work_2%qdd == b) .and. &
               maxval(abs(work_2%normal - normal_a)) > 1e-3_wp*maxval(abs(normal_a)), &
               'workspace: each workspace holds the results of its own last evaluation (A''s kept while B''s computed)')
    call check(all(m%law_force(work_1, 1) == friction_a) .and. norm2(friction_a) > 0 .and. &
               norm2(m%law_force(work_2, 1) - friction_a) > 1e-3_wp*norm2(friction_a), &
               'workspace: each workspace holds its own laws'' loads and factors (A''s friction kept while B''s computed)')
    call m%dynamics(work_1, 0.0_wp, q_a, s_a, again, st)
    call check(st%ok() .and. work_1%dynamics_reused == reused + 2, &
               'workspace: back at A with the first workspace after B: reused (the workspace still holds A)')
    call check(all(again == a) .and. all(work_1%normal == normal_a), &
               'workspace: back at A: A''s accelerations and normal forces bit for bit')
    call check(work_2%dynamics_reused == 0, 'workspace: the second workspace reused nothing')
  end subroutine cache_belongs_to_the_mechanism_state

  !> Two integrations (from A and from B) of copies of the sled, advanced in
  !> turns by output times, against each alone: bit for bit.
  subroutine interleaved_integrations()
    type(mechanism_ode_t), target :: alone_a, alone_b, turn_a, turn_b
    real(wp), allocatable :: ya(:, :), yb(:, :), y_a(:), y_b(:)
    type(ode_integrator_t) :: integ_a, integ_b
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: t
    integer :: k
    logical :: same
    opt%rtol = 1e-10_wp
    opt%atol = 1e-12_wp
    ! each alone
    alone_a%mechanism = sled
    call run_alone(alone_a, q_a, s_a, opt, ya)
    alone_b%mechanism = sled
    call run_alone(alone_b, q_b, s_b, opt, yb)
    ! in turns
    turn_a%mechanism = sled
    turn_b%mechanism = sled
    y_a = turn_a%initial_state(q_a, s_a)
    call turn_a%check_start(y_a, st)
    y_b = turn_b%initial_state(q_b, s_b)
    call turn_b%check_start(y_b, st)
    y_a = turn_a%initial_state(q_a, s_a)
    y_b = turn_b%initial_state(q_b, s_b)
    call integ_a%start(turn_a, 0.0_wp, y_a, opt, st)
    call integ_b%start(turn_b, 0.0_wp, y_b, opt, st)
    same = st%ok()
    do k = 1, n_out
      call integ_a%advance(k*dt, t, y_a, st)
      same = same .and. st%ok() .and. all(y_a == ya(:, k))
      call integ_b%advance(k*dt, t, y_b, st)
      same = same .and. st%ok() .and. all(y_b == yb(:, k))
    end do
    call check(same, 'interleaved: two integrations of one mechanism in turns, each with its own workspace, '// &
               'give the results of each alone bit for bit')
    call check(maxval(abs(ya(:, n_out) - yb(:, n_out))) > 1e-3_wp, 'interleaved: the two runs differ')
  end subroutine interleaved_integrations

  !> Two integrations (from A and from B) of the sled object itself, by two
  !> ODE objects that point to it, advanced in turns by output times, against
  !> each alone: bit for bit.
  subroutine one_mechanism_two_integrations()
    type(shared_ode_t), target :: alone_a, alone_b, turn_a, turn_b
    type(ode_integrator_t) :: integ_a, integ_b
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: ya(:, :), yb(:, :), y_a(:), y_b(:)
    real(wp) :: t
    integer :: k
    logical :: same
    opt%rtol = 1e-10_wp
    opt%atol = 1e-12_wp
    alone_a%mechanism => sled
    call run_shared(alone_a, q_a, s_a, opt, ya)
    alone_b%mechanism => sled
    call run_shared(alone_b, q_b, s_b, opt, yb)
    turn_a%mechanism => sled
    turn_b%mechanism => sled
    st = status_t()
    call sled%check_start(turn_a%work, q_a, st)
    call sled%check_start(turn_b%work, q_b, st)
    y_a = [q_a, s_a]
    y_b = [q_b, s_b]
    call integ_a%start(turn_a, 0.0_wp, y_a, opt, st)
    call integ_b%start(turn_b, 0.0_wp, y_b, opt, st)
    same = st%ok()
    do k = 1, n_out
      call integ_a%advance(k*dt, t, y_a, st)
      same = same .and. st%ok() .and. all(y_a == ya(:, k))
      call integ_b%advance(k*dt, t, y_b, st)
      same = same .and. st%ok() .and. all(y_b == yb(:, k))
    end do
    call check(same, 'one mechanism: two ODE objects integrate the same mechanism object in turns, each '// &
               'with its own workspace: each run equals its run alone bit for bit')
    call check(maxval(abs(ya(:, n_out) - yb(:, n_out))) > 1e-3_wp, 'one mechanism: the two runs differ')
  end subroutine one_mechanism_two_integrations

  !> One integration alone of the shared ODE from (q0, s0): the states at the output times.
  subroutine run_shared(sys, q0, s0, opt, out)
    type(shared_ode_t), intent(inout), target :: sys
    real(wp), intent(in) :: q0(:), s0(:)
    type(ode_options_t), intent(in) :: opt
    real(wp), allocatable, intent(out) :: out(:, :)
    type(ode_integrator_t) :: integ
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: t
    integer :: i
    call sys%mechanism%check_start(sys%work, q0, st)
    call check(st%ok(), 'one mechanism: the run alone starts: '//st%text())
    y = [q0, s0]
    allocate (out(size(y), n_out))
    call integ%start(sys, 0.0_wp, y, opt, st)
    do i = 1, n_out
      call integ%advance(i*dt, t, y, st)
      out(:, i) = y
    end do
    call check(st%ok(), 'one mechanism: the run alone: '//st%text())
  end subroutine run_shared

  !> One integration alone from (q0, s0): the states at the output times.
  subroutine run_alone(sys, q0, s0, opt, out)
    type(mechanism_ode_t), intent(inout), target :: sys
    real(wp), intent(in) :: q0(:), s0(:)
    type(ode_options_t), intent(in) :: opt
    real(wp), allocatable, intent(out) :: out(:, :)
    type(ode_integrator_t) :: integ
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: t
    integer :: i
    y = sys%initial_state(q0, s0)
    call sys%check_start(y, st)
    call check(st%ok(), 'interleaved: the run alone starts: '//st%text())
    y = sys%initial_state(q0, s0)
    allocate (out(size(y), n_out))
    call integ%start(sys, 0.0_wp, y, opt, st)
    do i = 1, n_out
      call integ%advance(i*dt, t, y, st)
      out(:, i) = y
    end do
    call check(st%ok(), 'interleaved: the run alone: '//st%text())
  end subroutine run_alone
end program test_mechanism_workspace
