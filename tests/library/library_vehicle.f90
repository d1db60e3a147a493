!> The shipped vehicle inputs (inputs/parts: a mat, a double ring, a raft,
!> a mat and a ring in the half-pipe and bowl, the mat over the jump that
!> flies) ridden through the library WITHOUT io (issue 24: a vehicle's ride
!> is a library call, design_vehicle_ride's run_vehicle_ride): the
!> descriptions are filled here by hand from the shipped files (each case
!> names its file; the values are copied from it, the defaults not given
!> there are the types' own), with the solver settings the fixture
!> cli_every_input runs them with (tests/cli/support/every_input.sh: the two
!> half-pipe-and-bowl rides at rtol 1e-6, atol 1e-5).
!>
!> This program links no io module (tests/CMakeLists.txt links it against
!> the design layer and the layers below it only). It prints one line per
!> number, `<input> <summary key> <value>` under the keys of the command's
!> --summary-json, and `TEXT <input> <key> <words>` for the summary's words
!> (the outcome, the water) and, with key `line`, the limits' verdict lines
!> of the printed summary (scenarios_sled vehicle_summarise), which
!> tests/library/library_without_io.sh compares with the command's.
program library_vehicle
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_text, only: format_integer, format_short
  use numerics_ode, only: ODE_ADAMS
  use geometry_tube, only: tube_surface_t
  use geometry_slide_builder, only: build_slide
  use geometry_description, only: geometry_description_t
  use kinetostatics_force_law_factory, only: law_spec
  use kinetostatics_impact, only: impact_law_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use water_run, only: water_description_t
  use water_flow, only: outcome_name
  use rider_vehicle, only: vehicle_kind_index
  use design_ride_evaluation, only: ride_limit_t, limit_bounds_text, limit_report_unit, spaced_unit
  use design_vehicle_ride, only: vehicle_ride_description_t, vehicle_ride_t, run_vehicle_ride
  use shipped_slides, only: demo_slide, halfpipe_slide, jump_slide, bowl_halfpipe_slide
  use library_lines, only: put, put_count, put_text, put_flights, expect_ok, failures
  implicit none (type, external)

  !> Runaway guard of the command's multibody runs (scenarios_mechanism min_mean_step).
  real(wp), parameter :: min_mean_step = 1e-4_wp

  call mat()
  call ring()
  call ring_child_adult()
  call bowl_halfpipe('mat')
  call bowl_halfpipe('ring')
  call raft()
  call mat_jump()
  if (failures > 0) then
    print '(a, i0, a)', 'FAIL ', failures, ' vehicle rides'
    error stop 1
  end if

contains

  !> inputs/parts/mat.nml: a mat with one rider (scale 1) down the demo
  !> slide in the computed water of &water (flow_rate only; no
  !> &water_solver: its defaults).
  subroutine mat()
    type(vehicle_ride_description_t) :: d
    d = vehicle('mat', 1, 1.0_wp, .true., 0.5_wp, 2.0_wp, demo_slide())
    d%water%flow_rate = 0.004_wp
    d%water%solver%output_step = 0.01_wp
    call ride('inputs/parts/mat.nml', d)
  end subroutine mat

  !> inputs/parts/ring.nml: a double ring with two riders down the half-pipe
  !> slide in its water (&water and &water_solver as the half-pipe ride's).
  subroutine ring()
    type(vehicle_ride_description_t) :: d
    d = vehicle('double_ring', 2, 1.0_wp, .true., 0.5_wp, 1.0_wp, halfpipe_slide())
    call halfpipe_water(d%water, 1.6707963267948966_wp, 1.4707963267948966_wp)
    call ride('inputs/parts/ring.nml', d)
  end subroutine ring

  !> inputs/parts/ring_child_adult.nml: the same double ring of larger
  !> tubes (R = 0.5 m, r = 0.17 m, 8 kg each), a child (scale 0.6) in front
  !> and an adult (1.08) behind.
  subroutine ring_child_adult()
    type(vehicle_ride_description_t) :: d
    d = vehicle('double_ring', 2, 1.0_wp, .true., 0.5_wp, 1.0_wp, halfpipe_slide())
    d%vehicle%scales(:2) = [0.6_wp, 1.08_wp]
    d%vehicle%ring_radii = [0.5_wp, 0.17_wp]
    d%vehicle%ring_mass = 8.0_wp
    call halfpipe_water(d%water, 1.6707963267948966_wp, 1.4707963267948966_wp)
    call ride('inputs/parts/ring_child_adult.nml', d)
  end subroutine ring_child_adult

  !> inputs/parts/bowl_halfpipe_mat.nml, bowl_halfpipe_ring.nml: a mat or
  !> a ring with one rider down the half-pipe and bowl slide in its water,
  !> started 1 m down at 1 m/s of u; the fixture's tolerances.
  subroutine bowl_halfpipe(kind)
    character(len=*), intent(in) :: kind
    type(vehicle_ride_description_t) :: d
    d = vehicle(kind, 1, 1.0_wp, .true., 1.0_wp, 1.0_wp, bowl_halfpipe_slide())
    call halfpipe_water(d%water, 1.7207963267948966_wp, 1.4207963267948966_wp)
    d%driver%ode%rtol = 1e-6_wp
    d%driver%ode%atol = 1e-5_wp
    call ride('inputs/parts/bowl_halfpipe_'//kind//'.nml', d)
  end subroutine bowl_halfpipe

  !> inputs/parts/raft.nml: a raft with four children (scale 0.7) down the
  !> half-pipe slide, dry.
  subroutine raft()
    call ride('inputs/parts/raft.nml', vehicle('raft', 4, 0.7_wp, .false., 0.5_wp, 1.0_wp, halfpipe_slide()))
  end subroutine raft

  !> inputs/parts/mat_jump.nml: the mat, dry, over the jump slide from 1 m
  !> at 2 m/s; it may fly and lands plastically (restitution 0) with
  !> Coulomb's mu the friction's (the reader's default for landing_mu);
  !> its airtime at most 1 s, its drop height at most 0.5 m.
  subroutine mat_jump()
    type(vehicle_ride_description_t) :: d
    d = vehicle('mat', 1, 1.0_wp, .false., 1.0_wp, 2.0_wp, jump_slide())
    d%vehicle%may_fly = .true.
    d%vehicle%landing = impact_law_t(restitution=0.0_wp, mu=0.0724419_wp)
    d%limits = [limit('airtime', 's', 1.0_wp), limit('drop_height', 'm', 0.5_wp)]
    call ride('inputs/parts/mat_jump.nml', d)
  end subroutine mat_jump

  !> A vehicle of &sled (its kind's name, riders, scale, in the water or
  !> dry) on the tube of `slide` (the water's slide too): Coulomb mu_D
  !> (thesis table 4.8) at both contacts, the start on the bottom (v0 =
  !> pi/2, phi0 = 0) at u0 with the rate du0; &solver as every shipped
  !> vehicle's: Adams, rtol 1e-10, atol 1e-9, 30 s (each ends at the
  !> slide's end), output every 0.01 s.
  function vehicle(kind, riders, scale, in_water, u0, du0, slide) result(d)
    character(len=*), intent(in) :: kind
    integer, intent(in) :: riders
    real(wp), intent(in) :: scale, u0, du0
    logical, intent(in) :: in_water
    type(geometry_description_t), intent(in) :: slide
    type(vehicle_ride_description_t) :: d
    type(tube_surface_t) :: tube
    type(status_t) :: st
    call build_slide(slide%slide, tube, st)
    call expect_ok(st, kind//': its slide')
    d%vehicle%kind = vehicle_kind_index(kind)
    d%vehicle%riders = riders
    d%vehicle%scales = scale
    d%vehicle%in_water = in_water
    d%sled%params%friction = [law_spec('coulomb', 'mu', 0.0724419_wp)]
    d%sled%q0 = [u0, 1.5707963267948966_wp, 0.0_wp]
    d%sled%qd0 = [du0, 0.0_wp, 0.0_wp]
    allocate (d%surface, source=tube)
    if (in_water) allocate (d%water%slide, source=tube)
    allocate (d%limits(0))
    d%driver%ode%method = ODE_ADAMS
    d%driver%ode%rtol = 1e-10_wp
    d%driver%ode%atol = 1e-9_wp
    d%driver%t_end = 30
    d%driver%output_step = 0.01_wp
    d%driver%min_mean_step = min_mean_step
    d%driver%progress_seconds = 0
    d%driver%label = 'sled'
  end function vehicle

  !> &water and &water_solver of the half-pipe rides: the start's edges,
  !> f1-f3 of the thesis's fit, the table step, Adams at rtol 1e-10, atol
  !> 1e-9, output every 0.005 s.
  subroutine halfpipe_water(water, v_left, v_right)
    type(water_description_t), intent(inout) :: water
    real(wp), intent(in) :: v_left, v_right
    water%flow_rate = 0.004_wp
    water%start%v_left = v_left
    water%start%v_right = v_right
    water%f1 = 0.0274748_wp
    water%f2 = 0.138285_wp
    water%f3 = 0.979822_wp
    water%table_step = 0.1_wp
    water%solver%ode%method = ODE_ADAMS
    water%solver%ode%rtol = 1e-10_wp
    water%solver%ode%atol = 1e-9_wp
    water%solver%output_step = 0.005_wp
  end subroutine halfpipe_water

  !> A maximum of `quantity` in `unit` (its report unit: no conversion).
  function limit(quantity, unit, maximum) result(l)
    character(len=*), intent(in) :: quantity, unit
    real(wp), intent(in) :: maximum
    type(ride_limit_t) :: l
    l%quantity = quantity
    l%unit = unit
    l%has_maximum = .true.
    l%maximum = maximum
    l%given_maximum = maximum
  end function limit

  !> The ride through the library, printed under the summary's keys.
  subroutine ride(name, d)
    character(len=*), intent(in) :: name
    type(vehicle_ride_description_t), intent(in) :: d
    type(vehicle_ride_t), target :: r
    class(mechanism_ode_t), pointer :: sys
    character(len=*), parameter :: axes(3) = [character(len=12) :: 'longitudinal', 'lateral', 'normal']
    character(len=*), parameter :: contacts(2) = [character(len=5) :: 'rear', 'front']
    integer :: k, i, n, exceeded
    call run_vehicle_ride(d, r)
    call expect_ok(r%status, name)
    if (.not. r%status%ok()) return
    sys => r%model()
    n = sys%series%n
    call put(name, 'simulated_time', sys%series%time(n))
    call put(name, 'u_final', sys%series%q(1, n))
    call put_count(name, 'steps', int(r%driven%stats%steps))
    call put_count(name, 'rhs_evaluations', int(r%driven%stats%rhs_evaluations))
    call put_text(name, 'outcome', r%outcome)
    if (d%vehicle%in_water) then
      call put_text(name, 'water', 'computed, '//format_short(d%water%flow_rate)//' m^3/s, '// &
                    outcome_name(r%water%series%outcome)//' (its drag at both contacts)')
    end if
    call put(name, 'vehicle_width', r%width)
    call put(name, 'narrowest_section', r%narrowest)
    call put(name, 'vehicle_speed_max', maxval(r%speed))
    call put(name, 'vehicle_speed_final', r%speed(n))
    do k = 1, 3
      call put(name, 'vehicle_felt_'//trim(axes(k))//'_min', minval(r%felt(k, :)))
      call put(name, 'vehicle_felt_'//trim(axes(k))//'_max', maxval(r%felt(k, :)))
    end do
    do k = 1, 2
      i = maxloc(abs(r%wall_angle(k, :)), dim=1)
      call put(name, 'vehicle_'//trim(contacts(k))//'_wall_angle', r%wall_angle(k, i)*180/pi)
      i = maxloc(abs(r%wall_distance(k, :)), dim=1)
      call put(name, 'vehicle_'//trim(contacts(k))//'_wall_distance', r%wall_distance(k, i))
    end do
    if (d%vehicle%may_fly) call put_flights(name, r%flights, highest=.false.)
    if (.not. allocated(r%verdicts)) return
    exceeded = 0
    do k = 1, size(d%limits)
      associate (l => d%limits(k), v => r%verdicts(k))
        if (v%exceeded) then
          exceeded = exceeded + 1
          call put_text(name, 'line', 'LIMIT EXCEEDED: '//l%quantity//' '//limit_bounds_text(l)//'; worst '// &
                        format_short(v%worst)//spaced_unit(limit_report_unit(l%quantity))//' at arc length '// &
                        format_short(v%worst_where)//' m (first at '//format_short(v%first_where)//' m)')
        else
          call put_text(name, 'line', 'limit '//l%quantity//' '//limit_bounds_text(l)//': ok (closest '// &
                        format_short(v%worst)//spaced_unit(limit_report_unit(l%quantity))//' at arc length '// &
                        format_short(v%worst_where)//' m)')
        end if
      end associate
    end do
    call put_count(name, 'limits_exceeded', exceeded)
  end subroutine ride
end program library_vehicle
