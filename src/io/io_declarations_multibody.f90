!> The declarations of the surface and multibody groups (io_declaration):
!> &surface and the contact scenario's &shape (one declaration of what both
!> hold), &grid, &point_mass, &pendulum, &fourbar, &sled, &contact_model,
!> &body, &contact. A surface kind's and a force law's own parameters (a,
!> b, c, radius, mu, ...) are declared with the kind (base_spec, read by
!> io_kind_parameters), not here.
module io_declarations_multibody
  use base_kinds, only: wp
  use io_declaration, only: declaration_t, VALUE_REAL, VALUE_INTEGER, VALUE_LOGICAL, VALUE_WORDS
  implicit none (type, external)
  private
  public :: multibody_declarations

  type(declaration_t), parameter :: multibody_declarations(*) = [ &
    ! ---- &surface, &shape (+ the parameters of the kind)
    declaration_t(groups='shape', name='name', kind=VALUE_WORDS, default='none', &
      meaning='the shape''s name, which &contact shape_1, shape_2 give (required)'), &
    declaration_t(groups='surface shape', name='kind', kind=VALUE_WORDS, default='''plane''', &
      meaning='the surface: a kind of the registry (docs/inputs.md, "&surface"), or tube, slide, blended, '// &
      'bspline described by the geometry groups'), &
    declaration_t(groups='surface shape', name='origin', shape='3', unit='m', default='0, 0, 0', low=-1e6_wp, &
      high=1e6_wp, meaning='where the surface''s own origin is placed'), &
    declaration_t(groups='surface shape', name='angles_deg', shape='3', unit='deg', default='0, 0, 0', &
      low=-360.0_wp, high=360.0_wp, meaning='its orientation, Cardan angles x-y''-z'''''), &
    declaration_t(groups='surface shape', name='geometry_file', kind=VALUE_WORDS, default='''''', &
      meaning='namelist file with the geometry groups of a tube, slide, blended or bspline surface (relative '// &
      'to this input''s folder, or builtin:demo_slide)'), &
    ! ---- &grid (scenario geometry)
    declaration_t(groups='grid', name='n_u', kind=VALUE_INTEGER, unit='1', default='400', low=2.0_wp, &
      high=1e5_wp, meaning='points of the written surface grid along u'), &
    declaration_t(groups='grid', name='n_v', kind=VALUE_INTEGER, unit='1', default='48', low=2.0_wp, &
      high=1e4_wp, meaning='points of the grid across (along v); n_u x n_v at most 2 x 10^7'), &
    declaration_t(groups='grid', name='n_frames', kind=VALUE_INTEGER, unit='1', default='400', low=2.0_wp, &
      high=1e5_wp, meaning='samples of the centerline''s frames'), &
    ! ---- &point_mass (+ the parameters of the friction law)
    declaration_t(groups='point_mass', name='mass', unit='kg', default='1', low=1e-6_wp, high=1e6_wp, &
      meaning='mass'), &
    declaration_t(groups='point_mass', name='u0', unit='surface parameter (m on a plane)', default='0', &
      low=-1e6_wp, high=1e6_wp, meaning='surface coordinate u at t = 0, inside the domain'), &
    declaration_t(groups='point_mass', name='v0', unit='surface parameter (m on a plane)', default='0', &
      low=-1e6_wp, high=1e6_wp, meaning='surface coordinate v at t = 0, inside the domain'), &
    declaration_t(groups='point_mass', name='du0', unit='surface parameter per s', default='0', low=-1e3_wp, &
      high=1e3_wp, meaning='rate of u at t = 0'), &
    declaration_t(groups='point_mass', name='dv0', unit='surface parameter per s', default='0', low=-1e3_wp, &
      high=1e3_wp, meaning='rate of v at t = 0'), &
    declaration_t(groups='point_mass', name='gravity', shape='3', unit='m/s^2', default='0, 0, -9.80665', &
      low=-1e3_wp, high=1e3_wp, meaning='gravity vector'), &
    declaration_t(groups='point_mass sled contact', name='friction', kind=VALUE_WORDS, default='''none''', &
      meaning='none, or a force law of the registry on the slip, its parameters beside it (docs/inputs.md, '// &
      '"&point_mass"; a sled: at both contacts)'), &
    declaration_t(groups='point_mass', name='sigma', unit='1', default='1', low=-1.0_wp, high=1.0_wp, &
      meaning='side of the Darboux frame''s normal (thesis 3.38): +1 or -1'), &
    declaration_t(groups='point_mass', name='alpha_u', unit='1', default='1', low=-1e3_wp, high=1e3_wp, &
      meaning='the frame''s x axis along alpha_u r_u + alpha_v r_v (thesis 3.41), not both 0'), &
    declaration_t(groups='point_mass', name='alpha_v', unit='1', default='0', low=-1e3_wp, high=1e3_wp, &
      meaning='see alpha_u'), &
    ! ---- &pendulum
    declaration_t(groups='pendulum', name='links', kind=VALUE_INTEGER, unit='1', default='1', low=1.0_wp, &
      high=2.0_wp, meaning='one or two links'), &
    declaration_t(groups='pendulum', name='length', shape='per link', unit='m', default='1, 1', low=1e-3_wp, &
      high=1e3_wp, meaning='link lengths'), &
    declaration_t(groups='pendulum', name='mass', shape='per link', unit='kg', default='1, 1', low=1e-6_wp, &
      high=1e6_wp, meaning='link masses'), &
    declaration_t(groups='pendulum', name='inertia', shape='per link', unit='kg m^2', default='0, 0', &
      low=0.0_wp, high=1e6_wp, meaning='moments of inertia about the centres of mass'), &
    declaration_t(groups='pendulum', name='theta0', shape='per link', unit='rad', default='0.5, 0', &
      low=-100.0_wp, high=100.0_wp, meaning='angles at t = 0'), &
    declaration_t(groups='pendulum', name='dtheta0', shape='per link', unit='rad/s', default='0, 0', &
      low=-1e4_wp, high=1e4_wp, meaning='their rates at t = 0'), &
    declaration_t(groups='pendulum', name='gravity', shape='3', unit='m/s^2', default='0, 0, -9.80665', &
      low=-1e3_wp, high=1e3_wp, meaning='gravity vector'), &
    ! ---- &fourbar
    declaration_t(groups='fourbar', name='a', unit='m', default='0.2', low=1e-3_wp, high=1e3_wp, &
      meaning='crank length'), &
    declaration_t(groups='fourbar', name='b', unit='m', default='0.6', low=1e-3_wp, high=1e3_wp, &
      meaning='coupler length'), &
    declaration_t(groups='fourbar', name='c', unit='m', default='0.5', low=1e-3_wp, high=1e3_wp, &
      meaning='rocker length'), &
    declaration_t(groups='fourbar', name='d', unit='m', default='0.7', low=1e-3_wp, high=1e3_wp, &
      meaning='ground length'), &
    declaration_t(groups='fourbar', name='mass', shape='3', unit='kg', default='0.5, 1, 0.8', low=1e-6_wp, &
      high=1e6_wp, meaning='masses of crank, coupler, rocker'), &
    declaration_t(groups='fourbar', name='gravity', shape='3', unit='m/s^2', default='0, -9.80665, 0', &
      low=-1e3_wp, high=1e3_wp, meaning='gravity vector'), &
    declaration_t(groups='fourbar', name='crank0', unit='rad', default='0', low=-100.0_wp, high=100.0_wp, &
      meaning='crank angle at t = 0'), &
    declaration_t(groups='fourbar', name='dcrank0', unit='rad/s', default='10', low=-1e4_wp, high=1e4_wp, &
      meaning='its rate at t = 0'), &
    declaration_t(groups='fourbar', name='branch', kind=VALUE_INTEGER, unit='1', default='1', low=-1.0_wp, &
      high=1.0_wp, meaning='+1: the coupler''s joint to the left of B->D, -1: right (not 0)'), &
    ! ---- &sled (+ the parameters of the friction law)
    declaration_t(groups='sled', name='length', unit='m', default='0.5', low=1e-3_wp, high=100.0_wp, &
      meaning='distance of the two runners'' contacts'), &
    declaration_t(groups='sled', name='mass', unit='kg', default='10', low=1e-3_wp, high=1e6_wp, &
      meaning='mass'), &
    declaration_t(groups='sled', name='inertia', shape='3', unit='kg m^2', default='0.02, 0.25, 0.25', &
      low=0.0_wp, high=1e6_wp, meaning='principal moments, each at most the sum of the other two'), &
    declaration_t(groups='sled', name='gravity', shape='3', unit='m/s^2', default='0, 0, -9.80665', &
      low=-1e3_wp, high=1e3_wp, meaning='gravity vector'), &
    declaration_t(groups='sled', name='sigma', unit='1', default='1', low=-1.0_wp, high=1.0_wp, &
      meaning='side of the normal: +1 or -1'), &
    declaration_t(groups='sled', name='alpha_u', unit='1', default='1', low=-1e3_wp, high=1e3_wp, &
      meaning='the frame''s x axis along alpha_u r_u + alpha_v r_v, not both 0'), &
    declaration_t(groups='sled', name='alpha_v', unit='1', default='0', low=-1e3_wp, high=1e3_wp, &
      meaning='see alpha_u'), &
    declaration_t(groups='sled', name='u0', unit='surface parameter', default='0', low=-1e6_wp, high=1e6_wp, &
      meaning='surface coordinate u at t = 0'), &
    declaration_t(groups='sled', name='v0', unit='surface parameter', default='0', low=-1e6_wp, high=1e6_wp, &
      meaning='surface coordinate v at t = 0'), &
    declaration_t(groups='sled', name='phi0', unit='rad', default='0', low=-100.0_wp, high=100.0_wp, &
      meaning='heading at t = 0'), &
    declaration_t(groups='sled', name='du0', unit='surface parameter per s', default='0', low=-1e3_wp, &
      high=1e3_wp, meaning='rate of u at t = 0'), &
    declaration_t(groups='sled', name='dv0', unit='surface parameter per s', default='0', low=-1e3_wp, &
      high=1e3_wp, meaning='rate of v at t = 0'), &
    declaration_t(groups='sled', name='dphi0', unit='rad/s', default='0', low=-1e3_wp, high=1e3_wp, &
      meaning='rate of the heading at t = 0'), &
    declaration_t(groups='sled', name='vehicle', kind=VALUE_WORDS, default='''bar''', &
      choices='bar mat sitting ring double_ring raft', meaning='what slides (docs/vehicles.md): the bar of length, '// &
      'mass and inertia, or a vehicle with its riders, built from riders and scale'), &
    declaration_t(groups='sled', name='riders', kind=VALUE_INTEGER, unit='1', default='1', low=1.0_wp, high=4.0_wp, &
      meaning='riders on the vehicle: mat, sitting and ring 1, double_ring 1-2, raft 1-4 (not for the bar)'), &
    declaration_t(groups='sled', name='scale', unit='1', default='1', low=0.6_wp, high=1.1_wp, &
      meaning='every rider''s size: height scale x 1.741 m, mass scale^3 x 73.0 kg (0.6: a small child, 1.1: a '// &
      'tall adult; not for the bar); scales gives each rider''s'), &
    declaration_t(groups='sled', name='scales', shape='per rider', unit='1', default='none', low=0.6_wp, &
      high=1.1_wp, meaning='each rider''s size as scale, rider by rider (a double ring''s first in the front '// &
      'ring, a raft''s first at the rear); none given: scale (docs/vehicles.md)'), &
    declaration_t(groups='sled', name='mat_length', unit='m', default='1', low=0.3_wp, high=3.0_wp, &
      meaning='the mat''s length, its two contacts'' distance (vehicle = ''mat'' only)'), &
    declaration_t(groups='sled', name='mat_width', unit='m', default='0.6', low=0.2_wp, high=1.5_wp, &
      meaning='the mat''s width (vehicle = ''mat'' only; the width check, docs/vehicles.md)'), &
    declaration_t(groups='sled', name='mat_thickness', unit='m', default='0.04', low=0.005_wp, high=0.3_wp, &
      meaning='the mat''s thickness: its rider lies on it (vehicle = ''mat'' only)'), &
    declaration_t(groups='sled', name='mat_mass', unit='kg', default='1.5', low=0.1_wp, high=50.0_wp, &
      meaning='the mat''s mass, a solid box (vehicle = ''mat'' only)'), &
    declaration_t(groups='sled', name='ring_radii', shape='2', unit='m', default='0.45, 0.15', low=0.05_wp, &
      high=1.5_wp, meaning='a ring''s torus: R from its centre to the tube''s centre, r the tube''s, r < R (ring, '// &
      'double_ring only)'), &
    declaration_t(groups='sled', name='ring_mass', unit='kg', default='7', low=0.5_wp, high=100.0_wp, &
      meaning='the mass of each ring, a thin-walled torus (ring, double_ring only)'), &
    declaration_t(groups='sled', name='raft_radii', shape='2', unit='m', default='0.75, 0.22', low=0.05_wp, &
      high=3.0_wp, meaning='the raft''s torus: R from its centre to the tube''s centre, r the tube''s, r < R '// &
      '(vehicle = ''raft'' only)'), &
    declaration_t(groups='sled', name='raft_mass', unit='kg', default='30', low=1.0_wp, high=1000.0_wp, &
      meaning='the raft''s mass with its floor, as a thin-walled torus (vehicle = ''raft'' only)'), &
    declaration_t(groups='sled', name='raft_floor', unit='m', default='0.03', low=0.0_wp, high=1.0_wp, &
      meaning='the height of the floor the raft''s riders sit on, at most 2 r (vehicle = ''raft'' only)'), &
    declaration_t(groups='sled', name='water', kind=VALUE_WORDS, &
      default='''computed'' (a vehicle), ''dry'' (the bar)', &
      choices='computed dry', meaning='a vehicle rides in the water computed on the slide (&water, &water_solver, '// &
      '&inlet; the water''s drag at both contacts, docs/vehicles.md, "In the water") or dry; the bar rides dry'), &
    declaration_t(groups='sled', name='may_fly', kind=VALUE_LOGICAL, default='.false.', &
      meaning='a vehicle flies: where a contact''s normal force falls to zero it leaves the slide and the ride '// &
      'goes on, on the other contact or in the air, until it lands (docs/vehicles.md, "Flight"); .false.: a '// &
      'lift-off ends the run'), &
    declaration_t(groups='sled', name='landing_restitution', unit='1', default='0', low=0.0_wp, high=1.0_wp, &
      meaning='restitution e of a vehicle''s landing (0: plastic; with may_fly only)'), &
    declaration_t(groups='sled', name='landing_mu', unit='1', default='none', low=0.0_wp, high=10.0_wp, &
      meaning='Coulomb mu during a vehicle''s landing (with may_fly only; none given: the friction law''s mu, '// &
      'else 0)'), &
    declaration_t(groups='sled', name='drag_area', unit='m^2', default='0', low=0.0_wp, high=1e3_wp, &
      meaning='C_d A of the air''s quadratic drag on the bar at its centre of mass (docs/contact.md, Air drag; '// &
      '0: none)'), &
    declaration_t(groups='sled contact_model point_mass', name='air_density', unit='kg/m^3', default='1.2041', &
      low=0.0_wp, high=1e3_wp, meaning='density of the air whose drag the bodies (the mass) with a drag_area '// &
      'feel (default: dry air at 20 C, 101.325 kPa)'), &
    declaration_t(groups='sled contact_model point_mass', name='wind', shape='3', unit='m/s', default='0, 0, 0', &
      low=-1e3_wp, high=1e3_wp, meaning='velocity of that air (world): the drag acts on a body''s velocity '// &
      'relative to it'), &
    ! ---- the contact scenario: &contact_model, &body, &contact (+ the parameters of the friction law)
    declaration_t(groups='contact_model', name='gravity', shape='3', unit='m/s^2', default='0, 0, -9.80665', &
      low=-1e3_wp, high=1e3_wp, meaning='gravity vector'), &
    declaration_t(groups='body', name='name', kind=VALUE_WORDS, default='none', &
      meaning='the body''s name (required, unique, not ''ground'')'), &
    declaration_t(groups='body', name='mass', unit='kg', default='1', low=0.0_wp, high=1e9_wp, open_low=.true., &
      meaning='mass'), &
    declaration_t(groups='body', name='solid_of', kind=VALUE_WORDS, default='none', meaning='a closed &shape: '// &
      'the centre of mass and inertia of the homogeneous solid it encloses (excludes centre, inertia, products)'), &
    declaration_t(groups='body', name='centre', shape='3', unit='m', default='0, 0, 0', low=-1e6_wp, high=1e6_wp, &
      meaning='centre of mass, body axes'), &
    declaration_t(groups='body', name='inertia', shape='3', unit='kg m^2', default='none', low=0.0_wp, &
      high=1e12_wp, meaning='moments of inertia about the centre along the body axes (required without solid_of)'), &
    declaration_t(groups='body', name='products', shape='3', unit='kg m^2', default='0, 0, 0', low=-1e12_wp, &
      high=1e12_wp, meaning='products of inertia I_xy, I_xz, I_yz about the centre'), &
    declaration_t(groups='body', name='position', shape='3', unit='m', default='0, 0, 0', low=-1e6_wp, &
      high=1e6_wp, meaning='start: origin of the body frame (world); its contact moves it until it touches'), &
    declaration_t(groups='body', name='angles_deg', shape='3', unit='deg', default='0, 0, 0', low=-360.0_wp, &
      high=360.0_wp, meaning='start orientation, Cardan angles: body axes = Rx Ry Rz'), &
    declaration_t(groups='body', name='velocity', shape='3', unit='m/s', default='0, 0, 0', low=-1e4_wp, &
      high=1e4_wp, meaning='start velocity of the body frame''s origin (world)'), &
    declaration_t(groups='body', name='angular_velocity', shape='3', unit='rad/s', default='0, 0, 0', &
      low=-1e5_wp, high=1e5_wp, meaning='start angular velocity (world)'), &
    declaration_t(groups='body point_mass', name='drag_area', unit='m^2', default='0', low=0.0_wp, high=1e3_wp, &
      meaning='C_d A, drag coefficient times reference area: the air''s quadratic drag at the centre of mass '// &
      'against its velocity relative to the air (a body: in flight and in contact; docs/contact.md, Air drag; '// &
      '0: none)'), &
    declaration_t(groups='contact', name='name', kind=VALUE_WORDS, default='none', &
      meaning='the contact''s name, prefix of its coordinates and outputs (required, unique)'), &
    declaration_t(groups='contact', name='body_1', kind=VALUE_WORDS, default='''ground''', &
      meaning='the body carrying the contact (placed before body_2): a &body name or ''ground'''), &
    declaration_t(groups='contact', name='shape_1', kind=VALUE_WORDS, default='none', &
      meaning='its surface: a &shape name'), &
    declaration_t(groups='contact', name='side_1', unit='1', default='1', low=-1.0_wp, high=1.0_wp, &
      meaning='side of shape_1 towards body_2, the sign of its normal (thesis 3.38): +1 or -1'), &
    declaration_t(groups='contact', name='body_2', kind=VALUE_WORDS, default='none', &
      meaning='the body this contact carries: a &body name'), &
    declaration_t(groups='contact', name='shape_2', kind=VALUE_WORDS, default='none', &
      meaning='its surface: a &shape name'), &
    declaration_t(groups='contact', name='side_2', unit='1', default='1', low=-1.0_wp, high=1.0_wp, &
      meaning='side of shape_2 towards body_1: +1 or -1'), &
    declaration_t(groups='contact', name='rolling', kind=VALUE_LOGICAL, default='.false.', &
      meaning='no slip (thesis 3.85), held by a velocity-level constraint; no friction law with it'), &
    declaration_t(groups='contact', name='level', kind=VALUE_WORDS, default='''position''', &
      choices='position velocity', meaning='position: exact contact, drift-free; velocity: the thesis''s '// &
      'velocity-level contact (appendix E), for comparison'), &
    declaration_t(groups='contact', name='chain', kind=VALUE_WORDS, default='open; loop with rolling', &
      choices='open loop', meaning='at position level: the open chain, or the relative chain closed by the '// &
      'five conditions (3.86)'), &
    declaration_t(groups='contact', name='start', kind=VALUE_WORDS, default='''closed''', choices='closed open', &
      meaning='closed: body_2 is moved onto shape_1 and starts touching; open: it starts where &body puts it, '// &
      'apart, in free flight until it lands, or a surface it may land on while another contact carries it '// &
      '(docs/contact.md, "Flight")'), &
    declaration_t(groups='contact', name='may_open', kind=VALUE_LOGICAL, default='.false.', &
      meaning='a lift-off (the normal force falling to zero) opens the contact and the body flies on, landing '// &
      'again with restitution, instead of ending the run; contacts of one body with the ground (docs/contact.md, '// &
      '"Flight")'), &
    declaration_t(groups='contact', name='restitution', unit='1', default='none', &
      low=0.0_wp, high=1.0_wp, meaning='energetic coefficient of restitution of the landings (start = ''open'' '// &
      'or may_open): the body bounces (docs/contact.md, "Impact law"); without it the run ends at the landing'), &
    declaration_t(groups='contact', name='impact_mu', unit='1', default='0', low=0.0_wp, high=10.0_wp, &
      meaning='Coulomb friction coefficient during an impact (with restitution)'), &
    declaration_t(groups='contact', name='close_speed', unit='m/s', default='0.01', low=0.0_wp, high=100.0_wp, &
      open_low=.true., meaning='a rebound slower than this closes the contact (with restitution; a plastic '// &
      'closing impulse): the run goes on with the closed contact (docs/contact.md, "Flight")')]
end module io_declarations_multibody
