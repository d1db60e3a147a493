!> The declarations of the ride's groups (&run, &solver and &water_solver,
!> &evaluation, &channel, &water, &inlet, &rider, &sweep): each variable once
!> (io_declaration). The rider's start and body and the water's inflow and
!> friction are shared by &sweep, which varies them: one declaration each,
!> so their bounds cannot disagree.
module io_declarations_ride
  use base_kinds, only: wp
  use io_declaration, only: declaration_t, VALUE_REAL, VALUE_INTEGER, VALUE_LOGICAL, VALUE_WORDS
  implicit none (type, external)
  private
  public :: ride_declarations

  type(declaration_t), parameter :: ride_declarations(*) = [ &
    ! ---- &run
    declaration_t(groups='run', name='scenario', kind=VALUE_WORDS, default='''point_mass''', &
      meaning='what to run (the words: `slidesim --help`)'), &
    declaration_t(groups='run', name='output', kind=VALUE_WORDS, default='''<scenario>.h5''', &
      meaning='result file (HDF5), up to 4096 characters; `slidesim -o FILE` overrides it'), &
    declaration_t(groups='run', name='title', kind=VALUE_WORDS, default='''''', &
      meaning='free text stored in the result file, up to 256 characters'), &
    ! ---- &solver, and the ride's &water_solver (the water's integration)
    declaration_t(groups='solver water_solver', name='method', kind=VALUE_WORDS, default='''adams''', &
      choices='adams bdf', meaning='integration method: variable-order Adams (non-stiff) or BDF (stiff)'), &
    declaration_t(groups='solver', name='accuracy', kind=VALUE_WORDS, default='''tolerances''', &
      choices='tolerances reference report', meaning='ride, sweep: tolerances (rtol, atol as given) or a preset '// &
      'of both integrators'': every report number within 1e-6 (reference) or 1e-4 (report) '// &
      'of rtol 1e-12 (docs/accuracy.md); a sweep giving no rtol, atol: report, not the default'), &
    declaration_t(groups='solver water_solver', name='rtol', unit='1', default='1e-10', low=1e-14_wp, &
      high=1e-2_wp, meaning='relative tolerance'), &
    declaration_t(groups='solver water_solver', name='atol', unit='units of the state', default='1e-10', &
      low=1e-16_wp, high=1.0_wp, meaning='absolute tolerance of every state component'), &
    declaration_t(groups='solver water_solver', name='max_steps', kind=VALUE_INTEGER, unit='1', &
      default='100000', low=1.0_wp, high=1e8_wp, meaning='most internal steps between two outputs'), &
    declaration_t(groups='solver water_solver', name='initial_step', unit='s', default='0', low=0.0_wp, &
      high=1e3_wp, meaning='first step size (0: CVODE''s estimate)'), &
    declaration_t(groups='solver water_solver', name='max_step', unit='s', default='0', low=0.0_wp, &
      high=1e6_wp, meaning='largest step size (0: no limit)'), &
    declaration_t(groups='solver water_solver', name='duration', unit='s', default='10', low=0.0_wp, &
      high=1e9_wp, open_low=.true., meaning='simulated time; the water (and a ride''s water): a bound only, '// &
      'left out it runs to the end of the slide'), &
    declaration_t(groups='solver water_solver', name='output_step', unit='s', default='0.01', low=1e-9_wp, &
      high=1e6_wp, meaning='time between stored samples, at most `duration`'), &
    ! ---- &evaluation
    declaration_t(groups='evaluation', name='fail_on_limit', kind=VALUE_LOGICAL, default='.false.', &
      meaning='a ride (or a sweep with a ride) over any limit ends with exit status 4, the result file complete'), &
    ! ---- &channel
    declaration_t(groups='channel', name='kind', kind=VALUE_WORDS, default='''straight''', &
      choices='straight helix s_bend', meaning='the closed-form tube: straight, helix or S-bend (docs/water.md)'), &
    declaration_t(groups='channel', name='radius', unit='m', default='0.5', low=0.01_wp, high=10.0_wp, &
      meaning='tube radius'), &
    declaration_t(groups='channel', name='incline_deg', unit='deg', default='10', low=0.0_wp, high=89.0_wp, &
      meaning='incline of the straight tube'), &
    declaration_t(groups='channel', name='length', unit='m', default='50', low=0.1_wp, high=1e4_wp, &
      meaning='length of the straight tube / x-extent of the S-bend'), &
    declaration_t(groups='channel', name='helix_radius', unit='m', default='3', low=0.01_wp, high=1e3_wp, &
      meaning='radius of the helix, more than `radius`'), &
    declaration_t(groups='channel', name='pitch', unit='m/rad', default='0.3', low=-100.0_wp, high=100.0_wp, &
      meaning='descent of the helix per radian'), &
    declaration_t(groups='channel', name='turn_sense', unit='1', default='1', low=-1.0_wp, high=1.0_wp, &
      meaning='+1 counter-clockwise seen from above, -1 clockwise (nothing between)'), &
    declaration_t(groups='channel', name='turns', unit='1', default='2', low=0.0_wp, high=1e3_wp, &
      open_low=.true., meaning='number of turns of the helix'), &
    declaration_t(groups='channel', name='amplitude', unit='m', default='1.5', low=-1e3_wp, high=1e3_wp, &
      meaning='S-bend amplitude (negative: mirrored)'), &
    declaration_t(groups='channel', name='wavenumber', unit='1/m', default='0.4', low=1e-4_wp, high=100.0_wp, &
      meaning='S-bend wavenumber'), &
    declaration_t(groups='channel', name='slope', unit='1', default='0.1', low=-10.0_wp, high=10.0_wp, &
      meaning='S-bend descent per metre'), &
    ! ---- &rider (the body and the start also in &sweep)
    declaration_t(groups='rider sweep', name='sex', kind=VALUE_WORDS, default='''male''', &
      choices='male female', meaning='which body table of de Leva'), &
    declaration_t(groups='rider sweep', name='mass', unit='kg', default='68.5', low=10.0_wp, high=300.0_wp, &
      meaning='body mass (thesis table 4.10)'), &
    declaration_t(groups='rider sweep', name='height', unit='m', default='1.78', low=0.5_wp, high=2.5_wp, &
      meaning='body height (thesis table 4.10)'), &
    declaration_t(groups='rider', name='com_height', unit='m', default='0.075', low=0.0_wp, high=0.5_wp, &
      open_low=.true., meaning='height of the segments'' centres of mass above the slide'), &
    declaration_t(groups='rider', name='friction', kind=VALUE_WORDS, default='''coulomb''', &
      meaning='the friction law at the three contacts: none, or a force law of the registry on the slip, its '// &
      'parameters beside it (docs/inputs.md, "&point_mass"); coulomb''s mu defaults to 0.0724419 here '// &
      '(thesis table 4.8)'), &
    declaration_t(groups='rider', name='drag', kind=VALUE_LOGICAL, default='.true.', &
      meaning='water drag on the three spheres'), &
    declaration_t(groups='rider', name='drag_radius', shape='3', unit='m', default='0.5, 0.05, 0.5', &
      low=0.0_wp, high=5.0_wp, open_low=.true., meaning='sphere radii: pelvis, heels, back (thesis 4.3)'), &
    declaration_t(groups='rider sled', name='water_density', unit='kg/m^3', default='1000', low=100.0_wp, &
      high=5000.0_wp, meaning='density of the water (drag)'), &
    declaration_t(groups='rider sled', name='water_viscosity', unit='m^2/s', default='1e-6', low=1e-8_wp, &
      high=1e-3_wp, meaning='kinematic viscosity of the water (Reynolds number of the drag)'), &
    declaration_t(groups='rider water', name='gravity', shape='3', unit='m/s^2', default='0, 0, -9.80665', &
      low=-1e3_wp, high=1e3_wp, meaning='gravity vector, one per run: a ride takes it from `&rider` or `&water` '// &
      '(both: the same, else refused); not zero for a rider (|gravity| is the unit g of felt accelerations)'), &
    declaration_t(groups='rider sweep', name='u0', unit='m', default='0.5', low=-1e6_wp, &
      high=1e6_wp, meaning='pelvis start: arc length along the slide''s centerline from its start'), &
    declaration_t(groups='rider sweep', name='v0', unit='rad', default='pi/2', low=-10.0_wp, high=10.0_wp, &
      meaning='pelvis start across the slide (pi/2: the bottom)'), &
    declaration_t(groups='rider sweep', name='heading0_deg', unit='deg', default='0', low=-180.0_wp, &
      high=180.0_wp, meaning='start heading of the body axis from down the slide, towards +v'), &
    declaration_t(groups='rider sweep', name='speed0', unit='m/s', default='1', low=0.0_wp, high=50.0_wp, &
      meaning='start speed along the body axis (0: at rest, a trap-door start steeper than mu holds)'), &
    declaration_t(groups='rider', name='min_speed', unit='m/s', default='0.05', low=0.0_wp, high=10.0_wp, &
      open_low=.true., meaning='the ride stops as stalled when the pelvis''s rate along the slide falls below'), &
    declaration_t(groups='rider', name='may_fly', kind=VALUE_LOGICAL, default='.false.', &
      meaning='where a contact''s normal force falls to zero it leaves the slide and the ride goes on '// &
      'through the flight, the whole rider''s too, until it lands (docs/rider.md, "Flight"); .false.: a '// &
      'lift-off ends the ride'), &
    declaration_t(groups='rider', name='landing_restitution', unit='1', default='0', low=0.0_wp, high=1.0_wp, &
      meaning='restitution e of a landing (0: plastic, on the water film; with may_fly only)'), &
    declaration_t(groups='rider', name='landing_mu', unit='1', default='0.0724419', low=0.0_wp, high=10.0_wp, &
      meaning='Coulomb mu during a landing (thesis table 4.8''s mu_D; with may_fly only)'), &
    declaration_t(groups='rider sled', name='limit_quantity', kind=VALUE_WORDS, shape='per limit, at most 20', &
      default='none', meaning='what limit k bounds (docs/rider.md lists the quantities), without gaps'), &
    declaration_t(groups='rider sled', name='limit_min', shape='per limit, at most 20', unit='the limit''s unit', &
      default='none', low=-1e6_wp, high=1e6_wp, meaning='lower bound of limit k'), &
    declaration_t(groups='rider sled', name='limit_max', shape='per limit, at most 20', unit='the limit''s unit', &
      default='none', low=-1e6_wp, high=1e6_wp, meaning='upper bound of limit k'), &
    declaration_t(groups='rider sled', name='limit_unit', kind=VALUE_WORDS, shape='per limit, at most 20', &
      default='none', meaning='the unit of limit k''s bounds (required; docs/rider.md)'), &
    ! ---- &water (flow_rate, f1, f2, f3 also in &sweep)
    declaration_t(groups='water sweep', name='flow_rate', unit='m^3/s', default='0.004', low=1e-6_wp, &
      high=1.0_wp, meaning='water inflow Q (refused with start = ''height_speed'', where Q = A w)'), &
    declaration_t(groups='water', name='start', kind=VALUE_WORDS, default='''edges''', &
      choices='edges height speed height_speed', meaning='which start values are given (docs/water.md)'), &
    declaration_t(groups='water', name='u0', unit='m', default='0', low=-1e6_wp, high=1e6_wp, &
      meaning='the first section: arc length along the slide''s centerline from its start'), &
    declaration_t(groups='water', name='v0', unit='rad', default='pi/2', low=-10.0_wp, high=10.0_wp, &
      meaning='water middle at the start (not with `start = ''edges''`)'), &
    declaration_t(groups='water', name='v_left0', unit='rad', default='pi/2 + 0.3', low=-10.0_wp, &
      high=10.0_wp, meaning='left edge of the water at the start (`edges` only), more than `v_right0`'), &
    declaration_t(groups='water', name='v_right0', unit='rad', default='pi/2 - 0.3', low=-10.0_wp, &
      high=10.0_wp, meaning='right edge of the water at the start (`edges` only)'), &
    declaration_t(groups='water', name='height0', unit='m', default='0.01', low=1e-6_wp, high=10.0_wp, &
      meaning='start height (`height`, `height_speed` only)'), &
    declaration_t(groups='water', name='speed0', unit='m/s', default='1', low=1e-3_wp, high=100.0_wp, &
      meaning='start speed (`speed`, `height_speed` only)'), &
    declaration_t(groups='water', name='beta0', unit='rad', default='0', low=-1.5_wp, high=1.5_wp, &
      meaning='start angle between flow and centerline (+ towards +v)'), &
    declaration_t(groups='water sweep', name='f1', unit='kg/m', default='0.0274748', low=0.0_wp, high=1e3_wp, &
      meaning='water friction f1 (4.7): constant (thesis table 4.3)'), &
    declaration_t(groups='water sweep', name='f2', unit='kg', default='0.138285', low=0.0_wp, high=1e3_wp, &
      meaning='water friction f2 (4.7): curvature'), &
    declaration_t(groups='water sweep', name='f3', unit='kg m', default='0.979822', low=0.0_wp, high=1e3_wp, &
      meaning='water friction f3 (4.7): increasing curvature ("splash")'), &
    declaration_t(groups='water', name='correction', kind=VALUE_WORDS, default='''full''', &
      choices='full no_radius off', meaning='Saint-Venant correction: full, without the dR/dt term, or none'), &
    declaration_t(groups='water', name='mass', unit='kg', default='1', low=1e-3_wp, high=1e3_wp, &
      meaning='virtual mass of the streamline'), &
    declaration_t(groups='water', name='min_speed', unit='m/s', default='0.05', low=1e-4_wp, high=10.0_wp, &
      meaning='below this speed the water has stalled (the run stops)'), &
    declaration_t(groups='water', name='min_criticality', unit='1', default='0.02', low=1e-6_wp, high=0.9_wp, &
      meaning='the run stops when 1 - 1/Fr^2 falls below this (correction on)'), &
    declaration_t(groups='water', name='stations', shape='list of at most 500', unit='m', default='none', &
      low=0.0_wp, high=1e6_wp, meaning='arc lengths of the report stations, increasing'), &
    declaration_t(groups='water', name='table_step', unit='m', default='0.1', low=1e-4_wp, high=1e3_wp, &
      meaning='spacing of the water table over arc length'), &
    declaration_t(groups='water', name='edges', kind=VALUE_LOGICAL, default='.true.', &
      meaning='solve the water edges at every output (else only at the table''s rows)'), &
    ! ---- &inlet (repeated: one group per inlet downstream of, or at, the &water start)
    declaration_t(groups='inlet', name='arc_length', unit='m', default='none', low=0.0_wp, high=1e6_wp, &
      meaning='where the inlet''s water joins: centerline arc length from the slide''s start, from the '// &
      '&water start to before the end (required)'), &
    declaration_t(groups='inlet', name='flow_rate', unit='m^3/s', default='none', low=1e-6_wp, high=1.0_wp, &
      meaning='flow rate the inlet adds (required)'), &
    declaration_t(groups='inlet', name='speed', unit='m/s', default='1', low=1e-3_wp, high=100.0_wp, &
      meaning='speed of the inlet''s water along the slide surface as it joins'), &
    declaration_t(groups='inlet', name='beta', unit='rad', default='0', low=-1.5_wp, high=1.5_wp, &
      meaning='angle of the inlet''s water to the centerline in the surface (+ towards +v), as `beta0`'), &
    ! ---- &sweep (besides the shared variables above, each a list or NAME_range)
    declaration_t(groups='sweep', name='mu', unit='1', default='0.0724419', low=0.0_wp, high=2.0_wp, &
      meaning='the rider''s Coulomb friction mu at the three contacts (0: none), with &rider friction = '// &
      '''coulomb'' or ''none'''), &
    declaration_t(groups='sweep', name='combine', kind=VALUE_WORDS, default='''cross''', &
      choices='cross paired', meaning='cross: every combination; paired: all swept variables element by element'), &
    declaration_t(groups='sweep', name='paired', kind=VALUE_WORDS, shape='at most 12', default='none', &
      choices='sex mass height mu u0 v0 heading0_deg speed0 flow_rate f1 f2 f3', &
      meaning='with `combine = ''cross''`: these vary together, element by element, as one axis'), &
    declaration_t(groups='sweep', name='threads', kind=VALUE_INTEGER, unit='1', default='0', low=0.0_wp, &
      high=1024.0_wp, meaning='OpenMP threads per rank; 0: OpenMP''s default'), &
    declaration_t(groups='sweep', name='progress_seconds', unit='s', default='10', low=0.0_wp, high=1e6_wp, &
      meaning='a progress line on standard error this often; 0: none'), &
    declaration_t(groups='sweep', name='csv_output', kind=VALUE_WORDS, &
      default='result file with `.csv`', meaning='the CSV summary (a path from the working folder, as `-o`)')]
end module io_declarations_ride
