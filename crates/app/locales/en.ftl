# Zeta Lab — English, the source catalogue (Project Fluent, https://projectfluent.org).
#
# Every string the interface shows has an id here. Other languages copy this file's ids
# into locales/<tag>.ftl; a message may use only the variables its English source uses.
# Variables hold text already in the language (a quantity with its unit, a name) or a
# count ($n), which selects plural forms: [one] …  *[other] ….
#
# The block "Declared strings" at the end is generated from the demo declarations:
# `ZETA_UPDATE_DOCS=1 cargo test -p zeta-app --test catalogues` rewrites it.

## The page

page-skip = Skip to the demo
page-demo = Demo
page-share = Share / Embed
page-loading = Loading the solver…
page-footer = Zeta Lab — every number on this page is computed in Rust (compiled to WebAssembly) from closed-form solutions.
page-parameters = Parameters
page-readouts = Readouts
page-about = About this demo
page-plot-in-view = Plot in view
page-presets = Presets
page-reset = Reset to defaults
page-exact-value = exact value
page-export-group = Export { $plot }
page-download = Download { $plot } as { $format }
page-play = Play
page-pause = Pause
page-sound-on = Sound on
page-sound-off = Sound off
page-sound-hint = Hear x(t): pitch follows displacement
page-anim-time = Animation time
page-time-words = time { $t } seconds
page-schematic = Animated schematic
page-dismiss = Dismiss notice
page-failed = Something went wrong and the demo was restarted: { $text }
page-no-demo = There is no demo called “{ $id }”; showing { $fallback }.
page-no-wasm = The solver could not be loaded ({ $text }). This page needs WebAssembly.
page-module-failed = This part of the page could not be loaded ({ $text }). Check the connection and try again.
page-copy = Copy
page-equation = Equation
page-tour-head = The paper, figure by figure
page-tour-open = Open this state in the demo
page-tour-paper = The paper says
page-tour-app = The app computes
page-tour-confirmed = Confirmed.
page-tour-differs = Differs.
page-tour-pending = Checking…
page-copied = Copied
page-copy-manual = Select and copy (Ctrl+C)
page-share-title = Share or embed “{ $title }”
page-embed-view = {" "}Embed view (no site header)
page-autoplay = {" "}Start the animation
page-theme = Theme{" "}
page-width = {" "}Width{" "}
page-height = {" "}Height{" "}
page-sliders-shown = Sliders shown
page-sliders-locked = Sliders locked
page-plots-shown = Plots shown
page-link = Link
page-embed-code = Embed code
page-preview = Preview of the embedded demo
page-close = Close
page-language = Language
page-language-nav = Language
page-demos-nav = Demos
page-no-script = Zeta Lab needs JavaScript and WebAssembly.
page-catalogue-failed = The { $name } catalogue could not be loaded ({ $text }); the page is in English.
page-provisional = { $value } (provisional)
page-study-progress = Computing the full result
page-readouts-shown = Readouts shown
page-state-token = State token
page-theme-auto = auto
page-theme-light = light
page-theme-dark = dark
page-theme-projector = projector (high contrast)
page-share-visitor-language = visitor’s language
page-share-language = {" "}Language{" "}
page-share-fullscreen = {" "}Full-screen button
page-share-ranges = Slider ranges and steps (leave empty to keep the declared ones)
page-share-col-slider = slider
page-share-col-from = from
page-share-col-to = to
page-share-col-step = step
page-share-range-from = { $label }: min
page-share-range-to = { $label }: max
page-share-range-step = { $label }: step
page-share-predict-task = Prediction task
page-share-none = none
page-share-predict = Students predict{" "}
page-share-predict-within = {" "}within{" "}
page-share-presets = Lecturer presets (carried in the link)
page-share-preset-example = e.g. Light damping
page-share-preset-add = Add the values on screen
page-share-preset-format = Format: name:key=value,key=value; next name:…
page-share-preset-default = Preset { $n }
page-share-preset-name = Name{" "}
page-share-preset-list = Presets{" "}
page-lecturer-presets = Lecturer presets
page-full-screen = Full screen
page-exit-full-screen = Exit full screen
page-no-stamp = This file carries no Zeta Lab view (only PNG, SVG and CSV exported by Zeta Lab do).
page-token-invalid = This saved view is not a Zeta Lab state token.
page-token-version = This saved view has format version “{ $version }”, which this page cannot read; nothing was changed.
page-token-damaged = This saved view is damaged and cannot be read; nothing was changed.
page-token-no-demo = This saved view names no demo this page has (“{ $demo }”); nothing was changed.
page-token-other-version-missing = This saved view comes from another version of Zeta Lab: { $missing } { $n ->
        [one] is not in it and starts
       *[other] are not in it and start
    } at the default.
page-token-other-version-unknown = This saved view comes from another version of Zeta Lab: { $unknown } { $m ->
        [one] is not known here and was
       *[other] are not known here and were
    } ignored.
page-token-other-version-both = This saved view comes from another version of Zeta Lab: { $missing } { $n ->
        [one] is not in it and starts
       *[other] are not in it and start
    } at the default; { $unknown } { $m ->
        [one] is not known here and was
       *[other] are not known here and were
    } ignored.
page-predict-title = Predict first
page-predict-hint = The plots and the { $label } stay hidden until you predict it. Type your prediction and press Enter.
page-predict-field = Your prediction of the { $label }
page-predict-field-unit = Your prediction of the { $label } ({ $unit })
page-predict-reveal = Reveal
page-predict-nan = “{ $text }” is not a number. Type a number such as { $example }.
page-predict-undefined = The { $label } is not defined for these parameters; change them and try again.
page-predict-result-inside = You predicted { $p }; the { $label } is { $v }: { $how }, within the tolerance { $tol }.
page-predict-result-outside = You predicted { $p }; the { $label } is { $v }: { $how }, outside the tolerance { $tol }.
page-predict-exact = exactly right
page-predict-high = { $d } too high
page-predict-low = { $d } too low

## Plots

plot-clipped = clipped: some values lie beyond the axes

## Notices (a parameter value that could not be used)

notice-value = { $problem ->
        [toggle] { $label } ({ $key }): “{ $value }” is not on or off; using the default.
        [option] { $label } ({ $key }): “{ $value }” is not one of { $options }; using the default.
        [number] { $label } ({ $key }): “{ $value }” is not a number; using the default { $default }.
        [range-empty] { $label } ({ $key }): range “{ $value }” is empty inside { $min } … { $max }; keeping the full range.
        [range-not-two-numbers] { $label } ({ $key }): range “{ $value }” is not two numbers “low,high”; keeping the full range.
        [step] { $label } ({ $key }): step “{ $value }” is not a number between 0 and { $span }; keeping { $step }.
       *[range] { $label } ({ $key }) = { $value } is outside { $min } … { $max }{ $unit }; using { $used }.
    }

## Exported files

export-csv-heading = Zeta Lab, demo { $demo }: { $title }
export-series = series { $n }

## Shared words: axes, regimes

axis-time = time t
axis-displacement = displacement x
axis-extension = extension x
axis-force = force F
axis-velocity = velocity v
axis-real-part = real part Re s
axis-imaginary-part = imaginary part Im s
regime-undamped = undamped
regime-underdamped = underdamped
regime-critically-damped = critically damped
regime-overdamped = overdamped
regime-negatively-damped = negatively damped
regime-neutral = neutral
regime-divergent = divergent

## Demos

### regimes

regimes-envelope = envelope ±A·e^(−ζωₙt)
regimes-series-response = x(t), { $regime }
regimes-describe-settles = { $regime }: { $swings ->
        [0] no swing past equilibrium before settling
        [one] swings past equilibrium once before settling
       *[other] swings past equilibrium { $swings } times before settling
    }, stays within 5 % of rest after { $time }, peak rebound { $rebound }.
regimes-describe-unsettled = { $regime }: { $swings ->
        [0] no swing past equilibrium before settling
        [one] swings past equilibrium once before settling
       *[other] swings past equilibrium { $swings } times before settling
    }, does not settle, peak rebound { $rebound }.
regimes-describe-undamped = undamped: oscillates forever with amplitude { $amplitude } at { $frequency }.
regimes-describe-growing = negatively damped: the response grows without bound, by a factor e every { $time }.
regimes-describe-at-rest = { $regime }: starts at rest at equilibrium.
regimes-poles = Poles at { $re1 } { $sign1 } { $im1 }i and { $re2 } { $sign2 } { $im2 }i 1/s, in the { $side ->
        [right] right (unstable)
       *[left] left (stable)
    } half-plane.
regimes-schematic = Mass on a spring and damper at t = { $time }: displaced { $displacement } from rest.

## Schematics

schematic-title = Schematic
schematic-circuit = Circuit
### rlc

rlc-axis-current = current i
rlc-axis-voltage = capacitor voltage v_C
rlc-envelope = envelope
rlc-series-critical = critical R = { $resistance }
rlc-schematic = Series RLC loop at t = { $time }: current { $current }, capacitor at { $voltage }.
rlc-describe-current = { $regime ->
        [undamped] R = { $resistance }, undamped (a lossless LC loop): the current oscillates forever at ω₀ = { $frequency }, between ±{ $bound } (all the energy passes to the inductor and back every half period).
        [underdamped] R = { $resistance } below the critical { $critical }, underdamped: the current rings at ω_d = { $ringing } (Q = { $q }), decaying as e^(−αt) with α = { $alpha }; it never exceeds { $bound }.
        [critical] R = { $resistance } equals the critical resistance, critically damped: one pulse of current (negative, the capacitor discharging) that returns to zero without reversing; it never exceeds { $bound }.
       *[overdamped] R = { $resistance } above the critical { $critical }, overdamped: one slow pulse of current (negative, the capacitor discharging) without reversing, slow time constant { $time }.
    }
rlc-describe-voltage = { $regime ->
        [undamped] R = { $resistance }, undamped (a lossless LC loop): the capacitor voltage swings between +{ $voltage } and −{ $voltage } forever at ω₀ = { $frequency }.
        [underdamped] R = { $resistance } below the critical { $critical }, underdamped: the capacitor voltage { $reversal ->
            [slight] reverses only slightly (at most { $rebound } of V₀, inside the band)
            [count] { $crossings ->
                [one] reverses polarity once before settling
               *[other] reverses polarity { $crossings } times before settling
            }
           *[never] never reverses polarity
        }, and { $settles ->
            [yes] stays within 5 % of V₀ after { $time }
           *[no] never settles
        }.
        [critical] R = { $resistance } equals the critical resistance, critically damped: the capacitor empties as fast as it can without reversing; it { $settles ->
            [yes] stays within 5 % of V₀ after { $time }
           *[no] never settles
        }.
       *[overdamped] R = { $resistance } above the critical { $critical }, overdamped: the capacitor discharges slowly without reversing; it { $settles ->
            [yes] stays within 5 % of V₀ after { $time }
           *[no] never settles
        }.
    }

### analogy

analogy-axis-response = normalised response
analogy-axis-energy = energy
analogy-series-x = x/x₀ mass
analogy-series-q = q/q₀ circuit
analogy-series-v = v/(x₀ωₙ) mass
analogy-series-i = i/(q₀ω₀) circuit
analogy-series-spring = ½kx² spring
analogy-series-capacitor = ½q²/C capacitor
analogy-series-mass = ½mv² mass
analogy-series-inductor = ½Li² inductor
analogy-series-total-mass = total, mass
analogy-series-total-circuit = total, circuit
analogy-caption-mechanical = mechanical
analogy-caption-electrical = electrical
analogy-schematic-title = Mechanical and electrical twins
analogy-describe-responses = { $regime } (ζ = { $zeta }): the mechanical x/x₀ and electrical q/q₀ coincide, as do the velocity v/(x₀ωₙ) and current i/(q₀ω₀) ({ $same ->
        [exact] identical to the last digit
       *[close] largest difference { $difference }
    }); { $motion ->
        [decaying] both oscillate at ω_d = { $frequency } and decay with time constant 1/(ζωₙ) = { $time }
        [lasting] both oscillate for ever at ω₀ = ωₙ = { $frequency }
       *[creeping] both creep back to rest without oscillating
    }.
analogy-describe-energy = At t = 0 all { $energy } is stored in the spring, and equally in the capacitor. { $exchange ->
        [swings] It swings to the mass (inductor), at most { $peak } at once, and back, twice per cycle
       *[passes] Without oscillating, at most { $peak } passes through the mass (inductor)
    }; { $loss ->
        [none] with no damper (resistor) it is all still there after { $time }
       *[heat] the damper c (resistor R) turns it into heat, leaving { $left } ({ $percent }) after { $time }
    }. The mechanical and electrical curves coincide.
analogy-schematic = At t = { $time }: the mass is displaced { $displacement } and moves at { $velocity }; the capacitor holds { $charge } and the current is { $current }. The same numbers in different units.

### universality

universality-axis-response = normalised response y/y₀
universality-axis-time = normalised time ωₙt
universality-series-critical = ζ = 1 (critical), for reference
universality-schematic-title = Machines A and B
universality-match-off = off
universality-match-on = on: B has the ωₙ and ζ of A
universality-match-too-light = not reachable: with its other parameters kept, B cannot go below ζ = { $zeta_min }; A has ζ = { $zeta }
universality-match-out-of-range = not reachable within the sliders: B would need { $symbol } = { $value }, outside { $low } … { $high }
universality-match-impossible = not reachable: A has no natural frequency
universality-describe-normalised = Released from rest: A ({ $machine_a }, ζ = { $zeta_a }) { $behaviour_a ->
        [forever] oscillates for ever
        [dies-away] oscillates and dies away
        [fastest] returns as fast as it can without overshoot
       *[creeps] creeps back without overshoot
    }; B ({ $machine_b }, ζ = { $zeta_b }) { $behaviour_b ->
        [forever] oscillates for ever
        [dies-away] oscillates and dies away
        [fastest] returns as fast as it can without overshoot
       *[creeps] creeps back without overshoot
    }. { $relation ->
        [coincide] The two curves coincide (largest difference { $gap }).
       *[differ] The curves differ by up to { $gap } of y₀.
    }{ $thermal ->
        [yes] { " " }A two-capacity thermal system cannot oscillate: its ζ is above 1 for any capacities and resistances.
       *[no] { "" }
    }
universality-describe-realtime = Real time over { $window }: time scale 1/ωₙ of A { $scale_a }, of B { $scale_b }; { $pace ->
        [faster] B runs { $factor } times faster than A
        [slower] B runs { $factor } times slower than A
       *[same] B keeps pace with A exactly
    }.
universality-schematic = At t = { $time }: A, { $machine_a }: { $coordinate_a } = { $value_a }; B, { $machine_b }: { $coordinate_b } = { $value_b }.
### quarter-car

quarter-car-legend-comfort = comfort { $low }, { $high }
quarter-car-legend-performance = performance { $low }, { $high }
quarter-car-legend-critical = critical { $zeta } (×)
quarter-car-legend-overdamped = overdamped { $zeta } (●)
quarter-car-group = { $group ->
        [comfort] comfort
        [performance] performance
        [critical] critical
       *[overdamped] overdamped
    }
quarter-car-crossings = { $count ->
        [0] does not cross equilibrium
        [one] crosses equilibrium once before settling
       *[other] crosses equilibrium { $count } times before settling
    }
quarter-car-crossings-inside-band = settles before crossing equilibrium (its rebound stays inside the band)
quarter-car-settles-after = stays within ±{ $band } of x₀ around rest after { $time }
quarter-car-does-not-settle = does not settle
quarter-car-rebound = peak rebound { $rebound } at { $time }
quarter-car-no-rebound = no rebound
quarter-car-describe-design = This design (ζ = { $zeta }, { $regime }): { $crossings }, { $settling }, { $rebound }.
quarter-car-describe-undamped = This design (ζ = 0, undamped): oscillates forever between ±{ $amplitude } at { $frequency }.
quarter-car-describe-unsettled = This design ({ $regime }): does not settle.
quarter-car-list-separator = {"; "}
quarter-car-describe-response = { $design } Preset family on this car, settling into ±{ $band } of x₀: { $family }.
quarter-car-member-settles = { $group } ζ = { $zeta } in { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } does not settle
quarter-car-two-sentences = { $first } { $second }
quarter-car-settling-fastest = Free-response settling time into ±{ $band } of x₀ against ζ for this car: fastest at ζ = { $zeta } ({ $time }), just past a jump; it jumps down each time a rebound drops inside the band.
quarter-car-settling-curve = Free-response settling time into ±{ $band } of x₀ against ζ.
quarter-car-settling-design = This design, ζ = { $zeta }, settles in { $time }.
quarter-car-settling-design-never = This design, ζ = { $zeta }, never settles.
quarter-car-sensitivity-range = With the sprung mass between { $low } and { $high } (±{ $variation }) and the same damper and spring, ζ ranges from { $min } to { $max } (nominal { $nominal }); the linear estimate is { $linear_min } to { $linear_max }.
quarter-car-sensitivity-undefined = The damping-ratio range is undefined for this design.
quarter-car-sensitivity-inside = The fastest-settling ζ = { $zeta } lies inside this range: loads that push ζ below it settle markedly later.
quarter-car-sensitivity-outside = The fastest-settling ζ = { $zeta } lies outside this range.
quarter-car-schematic = Quarter car at t = { $time }: the body is { $displacement } from rest ({ $side ->
        [above] above
       *[below] below
    }), road fixed.
quarter-car-settling-title = Settling time into ±{ $band } of x₀ against ζ
quarter-car-axis-zeta = damping ratio ζ
quarter-car-axis-zeta-fastest = damping ratio ζ (dashed: fastest ζ = { $zeta })
quarter-car-axis-settling-time = settling time t_s
quarter-car-axis-sprung-mass = sprung mass m
quarter-car-fastest = fastest ζ = { $zeta }
quarter-car-this-design = this design
quarter-car-nominal = nominal
quarter-car-road = road
quarter-car-band-label = ±{ $band } of x₀
quarter-car-series-design = this design, ζ { $zeta }

### quarter-car-2dof

quarter-car-2dof-describe-motion = Over { $road ->
        [bump] a bump
        [step] a step
        [sine] a sinusoidal road
       *[random] a random road
    } (largest road height { $road_peak }), the body moves at most { $body } (at { $body_time }) and the wheel { $wheel } (at { $wheel_time }).
quarter-car-2dof-describe-acceleration = Body acceleration peaks at { $peak } ({ $peak_g } g); over the run from rest, 0 to { $window }, its RMS is { $rms }.
quarter-car-2dof-describe-tyre-lift-off = Tyre deflection (wheel above road, positive = tyre unloading) ranges from { $low } to { $high }, RMS { $rms }; it reaches the static deflection { $limit } first at { $time }, where the tyre force falls to zero and the wheel leaves the road: lift-offs { $lift_offs }; time off the road { $airborne }.
quarter-car-2dof-describe-tyre-contact = Tyre deflection (wheel above road, positive = tyre unloading) ranges from { $low } to { $high }, RMS { $rms }; it stays below the static deflection { $limit }, so the tyre keeps contact.
quarter-car-2dof-describe-frf = Frequency response per unit road height, on log axes. The body follows slow road waves (ratio 1), peaks at { $body_peak } near body bounce { $body_frequency }, and is isolated above: { $at_20 } at 20 Hz. The tyre deflection peaks at { $tyre_peak } near wheel hop { $tyre_frequency }.
quarter-car-2dof-schematic = Quarter car at t = { $time }: body { $body }, wheel { $wheel }, road { $road } (drawn to a common scale).
quarter-car-2dof-schematic-title = Schematic
quarter-car-2dof-axis-height = height from equilibrium
quarter-car-2dof-axis-acceleration = acceleration z_s″
quarter-car-2dof-axis-tyre-deflection = tyre deflection z_u − u
quarter-car-2dof-axis-frequency = frequency f
quarter-car-2dof-axis-magnitude = magnitude per unit road height
quarter-car-2dof-series-road = road u
quarter-car-2dof-series-wheel = wheel z_u
quarter-car-2dof-series-body = body z_s
quarter-car-2dof-series-body-acceleration = body acceleration
quarter-car-2dof-series-rms = ± RMS
quarter-car-2dof-series-lift-off = lift-off (static deflection)
quarter-car-2dof-series-off-road = off the road
quarter-car-2dof-series-body-gain = body/road
quarter-car-2dof-series-tyre-gain = tyre defl./road
quarter-car-2dof-marker-road = road
### paper

paper-unavailable = this figure's demo is not available
paper-pending-plot = drawn once the whole app has loaded
paper-pending-mark = loading…
paper-pending-value = …
paper-pending = Checked as soon as the whole app has loaded, in a moment.
paper-figure = Figure { $number }
paper-section = Section { $number }
paper-section-figure = Section { $section }, Figure { $figure }
paper-near-agrees = The demo computes { $computed }, within the rounding of the paper's { $claimed } (tolerance ±{ $tolerance }).
paper-near-differs = The demo computes { $computed }, not the paper's { $claimed } (tolerance ±{ $tolerance }).
paper-below-agrees = The demo computes { $computed }, which is below the paper's bound of { $bound }.
paper-below-differs = The demo computes { $computed }, which is above the paper's bound of { $bound }.
paper-range = { $low } to { $high }
paper-range-agrees = The demo computes { $low } to { $high }, as the paper says.
paper-range-differs = The demo computes { $low } to { $high }, not the paper's range.
paper-peak = The maximum of |H(r)| found by search lies at r = { $found }, where the formula gives { $formula }.
paper-slope = Over the paper's step h = { $step } and five halvings (down to { $smallest }), the fitted slope is { $slope }.
paper-reason-context = { $verdict } { $context }
paper-exhibit-fig1a = Free response of the quarter car (m = 300 kg, k = 24 kN/m, x₀ = 60 mm) for comfort, performance, critical and overdamped settings.
paper-exhibit-fig1b = Settling time against damping ratio, with its minimum.
paper-exhibit-fig2a = Current in the series RLC loop (L = 0.5 H, C = 20 mF, V₀ = 12 V) as the resistance spans the regimes.
paper-exhibit-fig2b = Capacitor voltage of the same loop.
paper-exhibit-fig3a = Magnitude of the frequency response for a family of damping ratios.
paper-exhibit-fig3b = Phase of the frequency response.
paper-exhibit-fig4a = Euler and RK4 against the exact response of a lightly damped oscillator (ζ = 0.05, ωₙ = 2 rad/s) at h = 0.3 s.
paper-exhibit-fig4b = Maximum error against step size on log–log axes, with slopes.
paper-exhibit-fig5 = One equation in many machines: mechanical, electrical and other systems with the same a·y'' + b·y' + c·y = f(t).
paper-exhibit-table1 = The mechanical–electrical analogy: mass ↔ inductance, damper ↔ resistance, spring ↔ 1/capacitance.
paper-exhibit-table2 = The damping regimes: condition, roots, behaviour and examples.
paper-exhibit-table3 = The integration methods compared: error, order and stability at one step size.
paper-claim-fig1-zeta-optimum = A damping ratio of about 0.7 gives the shortest settling time (5 % band).
paper-claim-sec3-natural-frequency = The quarter car's natural frequency is about 8.9 rad/s (about 1.4 Hz).
paper-claim-sec4-critical-resistance = The loop is critically damped at R = 2√(L/C) = 10 Ω.
paper-claim-fig3-q-factor = Q = 10 at ζ = 0.05.
paper-claim-fig3-q-factor-light = Q = 50 at ζ = 0.01.
paper-claim-sec5-peak-frequency = The response peaks at ω = ωₙ√(1 − 2ζ²), just below ωₙ (checked at ζ = 0.1).
paper-claim-fig4-euler-error = At h = 0.3 s Euler's maximum error is about 0.08.
paper-claim-fig4-rk4-error = At h = 0.3 s RK4's maximum error is below 0.001.
paper-claim-fig4-euler-slope = Euler's error falls with slope ≈ 1 on the log–log plot.
paper-claim-sec7-mass-tolerance = A ±10 % uncertainty in the sprung mass moves ζ = 1.0 to between 0.91 and 1.10.
paper-claim-fig1-zeta-optimum-context = For a 2 % band the fastest-settling ζ is { $value } instead.
paper-claim-sec3-natural-frequency-context = In hertz: fₙ = { $value }.
paper-claim-fig4-euler-error-context = Euler is unstable at this step: |1 + hλ| = { $value } per step, so its error grows without bound.
paper-claim-fig4-rk4-error-context = RK4 is stable at this step (|R(hλ)| = { $value } per step), yet over the whole window its error exceeds the bound.
paper-claim-fig4-euler-slope-context = The order fitted over small steps, where the error is asymptotic, is { $value }.
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) varies as 1/√m, so a ±10 % mass moves it by only about ±5 % (ωₙ drops to { $value } at +10 %).
### resonance

resonance-axis-ratio = frequency ratio r = ω/ωₙ
resonance-axis-amplification = amplification |H| = X/(F₀/k)
resonance-axis-magnitude-db = magnitude 20·log₁₀|H|
resonance-axis-phase = phase ∠H (lag of x behind F)
resonance-plot-magnitude-db = Amplification |H(r)| in dB
resonance-family = family ζ = { $from } … { $to }
resonance-current = current ζ = { $zeta }
resonance-drive = drive r = { $ratio }
resonance-peak = peak
resonance-quadrature = −90° at r = 1
resonance-legend-width = half-power width r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2 up to r = { $upper }
resonance-legend-cutoff = −3 dB cut-off r = { $upper }
resonance-band-width = half-power points (|H| = |H|max/√2) at r = { $lower } and { $upper }: peak width r₂ − r₁ = { $width }
resonance-band-broad = |H| stays above |H|max/√2 from r = 0 up to r = { $upper }: the peak has no lower half-power point, so its half-power width is undefined
resonance-band-cutoff = |H| falls to 1/√2 of its static value (−3 dB) at the cut-off r = { $upper }; without a peak there is no half-power width
resonance-peak-at = resonant peak { $gain } at r = { $ratio }
resonance-no-peak = no resonant peak (ζ ≥ 1/√2): |H| only falls from 1 at r = 0
resonance-describe-magnitude = { $view ->
        [db] Magnitude in dB for ζ = { $zeta }: { $peak }; { $band }. At the drive r = { $drive } the amplification is { $gain }.
       *[linear] Magnitude for ζ = { $zeta }: { $peak }; { $band }. At the drive r = { $drive } the amplification is { $gain }.
    }
resonance-describe-phase = Phase of the displacement behind the force for ζ = { $zeta }: 0° at low frequency, −90° at r = 1 for every damping ratio, towards −180° above resonance; the smaller ζ, the sharper the switch. At the drive r = { $drive } the lag is { $degrees } ({ $radians } rad).
resonance-envelope = envelope ±E(t)
resonance-steady-amplitude = steady amplitude ±X
resonance-describe-time-growing = Driven from rest at r = { $ratio } (ω = { $omega }) for { $span }: no steady state; the amplitude grows, reaching { $largest }.
resonance-describe-time = { $case ->
        [beats] Driven from rest at r = { $ratio } (ω = { $omega }) for { $span }: the free and forced motions beat with period { $period } (time constant of the decay { $tau }), towards the steady amplitude { $amplitude }, lagging the force by { $lag }. Largest excursion shown { $largest }.
        [build-up] Driven from rest at r = { $ratio } (ω = { $omega }) for { $span }: at resonance the amplitude builds up towards the steady amplitude { $amplitude } with time constant 1/(ζωₙ) = { $tau }, lagging the force by { $lag }. Largest excursion shown { $largest }.
       *[transient] Driven from rest at r = { $ratio } (ω = { $omega }) for { $span }: after a transient (time constant { $tau }) it settles to the steady amplitude { $amplitude }, lagging the force by { $lag }. Largest excursion shown { $largest }.
    }
resonance-fixed-base = fixed base
resonance-schematic = Mass on a spring and damper over a fixed base, pushed by the force F(t) = { $force } (arrow above the mass) at t = { $time }: displaced { $displacement } from rest.
resonance-beats-visible = visible
resonance-beats-no-free-oscillation = none (no free oscillation, ζ ≥ 1)
resonance-beats-no-drive = none (constant force)
resonance-beats-same-frequency = none (driven at ω_d)
resonance-beats-too-fast = none (as fast as the oscillation)
resonance-beats-dies-out = none (the free motion dies out first)

### flutter

flutter-no-oscillation = no oscillation
flutter-series-h-section = 1940 H-section (teaching approx.)
flutter-series-box = streamlined box (flat plate, Theodorsen)
flutter-series-simplest = A₂* the simplest picture amounts to
flutter-series-simplest-line = simplest picture ζ_s − g·U
flutter-axis-reduced-velocity = reduced velocity U/(f·B) = 2π/K
flutter-axis-wind-speed = wind speed U
flutter-axis-effective-damping = effective damping ratio ζ_eff
flutter-axis-twist = twist θ
flutter-threshold = threshold 4Iζ_s/(ρB⁴) = { $value }
flutter-upper-pole = upper pole
flutter-lower-pole = lower pole
flutter-amplitude = amplitude ±a(t)
flutter-limit-cycle = limit cycle ±{ $amplitude }
flutter-describe-derivative = A₂* against reduced velocity for { $model ->
        [h] the 1940 H-section (teaching approximation, not measured values)
        [box] the streamlined box, idealised as a thin flat plate (Theodorsen's exact potential-flow values)
       *[simplest] the simplest picture (the A₂* its straight line in U amounts to)
    }: the twist grows where A₂* rises above 4Iζ_s/(ρB⁴).
flutter-describe-derivative-now = { $description } At U = { $speed } (K = { $k }, U/(fB) = { $reduced_velocity }) A₂* = { $a2 }, { $side ->
        [above] above
       *[below] below
    } the threshold { $threshold }.
flutter-describe-damping = Effective damping ratio of { $model ->
        [h] the 1940 H-section
        [box] the streamlined box
       *[simplest] the simplest picture
    } from ζ_s = { $zeta_s } in calm air; it { $crossing ->
        [inside] crosses zero at the critical speed { $speed }
        [beyond] would cross zero only at { $speed }, beyond the plotted { $limit }
       *[never] never crosses zero up to 100 m/s: the wind only adds damping
    }.
flutter-describe-damping-now = { $description } At U = { $speed } it is { $zeta }, { $sign ->
        [positive] positive (stable)
        [negative] negative (flutter)
       *[zero] zero
    }.
flutter-describe-damping-still = { $description } At this wind the deck does not oscillate.
flutter-describe-locus = Pole pair as the wind rises: { $re_calm } ± { $im_calm }i 1/s in calm air, { $re_end } ± { $im_end }i 1/s at { $limit }, { $crosses ->
        [yes] crossing the imaginary axis at U_crit
       *[no] never crossing the imaginary axis
    }.
flutter-describe-locus-now = { $description } At U = { $speed } the poles are { $re } ± { $im }i 1/s, in the { $side ->
        [right] right (unstable)
       *[left] left (stable)
    } half-plane.
flutter-oscillation = the oscillation
flutter-oscillation-at = the oscillation at { $frequency } Hz
flutter-describe-response = { $regime }: from an initial twist of { $twist }, { $oscillation } { $case ->
        [settling] grows to { $end } by the end of the plot ({ $window }), settling near the limit cycle of { $limit } (90 % of it after { $time })
        [slow] grows only to { $end } by the end of the plot ({ $window }); it would take { $time } to reach 90 % of the limit cycle of { $limit }
        [settled] settles onto the limit cycle of { $limit } by the end of the plot ({ $window })
        [grows] grows to { $end } by the end of the plot ({ $window })
       *[dies] dies down to { $end } by the end of the plot ({ $window })
    }.
flutter-describe-response-torn = { $description } A twist this large would have torn any deck apart long before; the bound is only a teaching assumption.
flutter-schematic-title = Deck cross-section
flutter-drawn-clipped = drawn clipped at { $angle }
flutter-drawn-true-scale = drawn true to scale
flutter-drawn-larger = drawn { $factor } times larger
flutter-drawn-note = ({ $drawn })
flutter-schematic = Bridge deck cross-section at t = { $time }: twisted { $twist } ({ $drawn }), wind { $wind } from the left.
flutter-wind = wind U = { $speed }
### integrators

integrators-join = { "; " }
integrators-legend-dp45-order = DP45: { $order }
integrators-overflow-note = overflow at t = { $time }
integrators-failed = failed
integrators-stable-yes = yes
integrators-stable-no = no
integrators-method-euler = forward Euler
integrators-method-symplectic-euler = symplectic Euler
integrators-method-heun = Heun
integrators-method-rk4 = RK4
integrators-legend-symplectic-euler = sympl. Euler ×
integrators-legend-euler = Euler
integrators-legend-heun = Heun
integrators-legend-dp45 = DP45 ● steps
integrators-legend-growing = { $legend } ×{ $growth }/step ↑
integrators-legend-order = { $legend }: { $order }
integrators-legend-no-fit = { $legend }: no fit
integrators-legend-dp45-no-order = DP45: no order
integrators-series-exact = exact
integrators-axis-error = error |x_num − x_exact|
integrators-axis-step = step h
integrators-axis-max-error = max error
integrators-axis-re = real part Re(hλ)
integrators-axis-im = imaginary part Im(hλ)
integrators-axis-evaluations = right-hand-side evaluations N
integrators-limit-up-to = stable for h ≤ { $step }
integrators-limit-every = stable for every h
integrators-limit-none = unstable for every h
integrators-method-overflows = { $method } overflows at t = { $time } (×{ $growth } per step)
integrators-method-diverges = { $method } diverges (×{ $growth } per step), max error { $error }
integrators-method-diverges-clipped = { $method } diverges (×{ $growth } per step, clipped), max error { $error }
integrators-method-bounded = { $method } stays bounded (×{ $growth } per step), max error { $error }
integrators-dp45-words = DP45 took { $steps } steps (tolerance { $tolerance }), max error { $error }
integrators-dp45-failed = DP45 failed: { $reason }
integrators-failed-underflow = the step size became too small to make progress at t = { $time } (the problem may be too stiff or singular)
integrators-failed-max-steps = gave up at t = { $time } after { $steps } steps
integrators-failed-non-finite = the solution became infinite or undefined at t = { $time } (try a smaller step)
integrators-describe-response = Each method against the exact decaying oscillation over { $duration } with h = { $step } ({ $steps } steps). { $methods }. The plot shows ±{ $range } of the exact amplitude; curves beyond it are clipped at the edge.
integrators-describe-response-last = Each method against the exact decaying oscillation over { $duration } with h = { $step } ({ $steps } steps, the last { $last } to end at T). { $methods }. The plot shows ±{ $range } of the exact amplitude; curves beyond it are clipped at the edge.
integrators-error-peak = { $method } largest { $error } at t = { $time }
integrators-error-peak-growing = { $method } largest { $error } at t = { $time }, growing
integrators-error-none = { $method } has no finite error
integrators-error-no-method = No method is switched on.
integrators-describe-error = Error |x_num − x_exact| on a logarithmic scale at each method's grid points (h = { $step }): { $methods }.
integrators-describe-error-clipped = Error |x_num − x_exact| on a logarithmic scale at each method's grid points (h = { $step }): { $methods }. Errors above { $clip } are clipped at the top.
integrators-fit = { $method } fitted slope { $slope } (h = { $from } … { $to })
integrators-fit-overflows = { $method } fitted slope { $slope } (h = { $from } … { $to }), overflows for h ≥ { $limit }
integrators-no-fit = { $method } no fit (too few points in the asymptotic range)
integrators-no-fit-overflows = { $method } no fit (too few points in the asymptotic range), overflows for h ≥ { $limit }
integrators-slope = slope { $order }
integrators-describe-convergence = Largest error at { $points } common check points against the step h, for up to { $levels } step sizes halving from { $from } (at most { $budget } steps per method in all, { $euler_budget } for forward Euler; finer steps are skipped). { $methods }. Each order is fitted over the asymptotic range only, drawn as the thick segment: the finest steps whose local slopes agree within { $spread }, with errors below { $ceiling } and above 1e-10 of x₀. Reference slopes 1 and 4 are dotted; the current h is the dashed vertical line. DP45 has no single h: see the work–precision plot.
integrators-off-scale = { $name } = { $value } (off scale)
integrators-path = hλ as h grows
integrators-z-real-pair = z = hλ = { $z1 } and { $z2 }
integrators-region-inside = { $method }: inside its region, |R| = { $growth }, { $limit }
integrators-region-outside = { $method }: outside its region, |R| = { $growth }, { $limit }
integrators-describe-stability = Stability regions |R(z)| ≤ 1 in the complex plane of z = hλ (inside each closed curve; forward Euler's is the disk |1 + z| ≤ 1). The system's two poles at h = { $step } give { $z }. { $methods }. Symplectic Euler is not a scalar map R(z): its 2×2 step matrix has spectral radius { $radius } here, { $limit }. DP45 chooses its own steps and keeps them stable.
integrators-work-words = { $method } from { $error_first } with { $work_first } evaluations to { $error_last } with { $work_last }
integrators-describe-work = Largest error against the work it cost, counted in evaluations of the right-hand side f, on log–log axes, for every method: fixed-step ones at the convergence study's step sizes (error at its common check points), DP45 at tolerances { $from } … { $to } (error over its accepted steps). Lower is more accurate, further left is cheaper; a method of order p falls with slope −p; DP45's runs are dots where the tolerance sets their steps and crosses where stability does. { $methods }.
integrators-provisional = Provisional: from a coarse study (at most { $budget } steps per method, { $euler_budget } for forward Euler; DP45 down to { $tol }) while the full one ({ $full_budget } and { $full_euler_budget } steps; DP45 down to { $full_tol }) runs. { $description }
integrators-runs-provisional = Provisional: the runs so far, to t = { $until } of { $duration }, while the rest are computed. { $description }
integrators-dp45-stability-runs = runs whose steps stability sets (more than { $share } of the steps at { $fraction } or more of its largest stable step): { $count }/{ $runs }
integrators-dp45-order = DP45 observed order { $order } (fitted over { $from } … { $to } evaluations, where the tolerance sets its steps); { $runs }
integrators-dp45-no-order = DP45 has no observed order: stability sets its steps, or too few runs remain in the asymptotic range; { $runs }

### nonlinear

nonlinear-effect-linear = linear
nonlinear-effect-hardening = hardening spring
nonlinear-effect-softening = softening spring
nonlinear-effect-stick-slip = stick-slip
nonlinear-effect-bump-stop = bump-stop impact
nonlinear-effect-asymmetric = asymmetric damper
nonlinear-effect-several = several at once
nonlinear-effect-escaped = escaped
nonlinear-join = { "; " }
nonlinear-differ = they differ by up to { $deviation } at t = { $time }
nonlinear-first-swing = first swing { $nonlinear } against the linear { $linear } (ratio { $ratio })
nonlinear-sticks-at = friction holds the mass at { $position } from { $time }
nonlinear-escapes = the nonlinear run leaves the plot (|x| > { $limit }) at { $time }
nonlinear-describe-response = { $effect }: both start together; { $clauses }.
nonlinear-describe-phase = Phase plane: both trajectories start at x = { $x0 }, v = { $v0 }. The linear one spirals in towards ({ $x_linear }, { $v_linear }); the nonlinear one ends at x = { $x_end }, v = { $v_end }, its largest speed { $speed } against the linear { $speed_linear }.
nonlinear-describe-spring = Restoring force against extension over ±{ $reach }: the linear spring is the straight line k·x; at the largest travel { $travel } the nonlinear force is { $force } against the linear { $linear }{ $stops ->
        [yes] , the bump stops adding { $rate } beyond ±{ $gap }.
       *[no] .
    }
nonlinear-describe-damper = Damper plus friction force against velocity over ±{ $speed }: at +{ $speed } (rebound) it is { $rebound }, at −{ $speed } (compression) { $compression }; the linear model's mean damper gives ±{ $linear }{ $coulomb ->
        [yes] ; sliding friction adds a jump of ±{ $friction } at v = 0, and at rest static friction holds up to ±{ $holding }.
       *[no] .
    }
nonlinear-axis-velocity-rebound = velocity v (+ rebound)
nonlinear-series-stops = bump stops ±{ $gap }
nonlinear-series-linear = linear model
nonlinear-series-nonlinear = nonlinear (RK4)
nonlinear-marker-sticks = sticks
nonlinear-marker-start = start
nonlinear-series-linear-spring = linear k·x
nonlinear-series-spring = k·x + k₃·x³ + stops
nonlinear-series-linear-damper = linear c̄·v
nonlinear-series-damper = damper + friction
nonlinear-schematic = Quarter car at t = { $time }: suspension extended { $extension }{ $stops ->
        [pressing] , pressing on a bump stop.
        [clear] , clear of the bump stops.
       *[none] .
    }

### uncertainty

uncertainty-quantity-zeta = damping ratio ζ
uncertainty-quantity-f0 = natural frequency f0
uncertainty-quantity-q = quality factor Q
uncertainty-quantity-bandwidth = half-power bandwidth
uncertainty-quantity-settling-time = free-response settling time (±5 %)
uncertainty-hist-title = Monte Carlo: { $quantity }
uncertainty-draws-provisional = { $draws } ({ $full } on the way)
uncertainty-band-nominal-mass = nominal m
uncertainty-band-lowest-corner = lowest-ζ corner
uncertainty-band-nominal = nominal
uncertainty-band-highest-corner = highest-ζ corner
uncertainty-never = never
uncertainty-band-suspension = Free response from { $start } with the sprung mass at +{ $percent } %, nominal and −{ $percent } %
uncertainty-band-rlc = Capacitor voltage from 1 V at the lowest-ζ corner, nominal and highest-ζ corner of the tolerance box
uncertainty-ignored-rlc = The RLC sliders are ignored.
uncertainty-ignored-suspension = The suspension sliders are ignored.
uncertainty-zeta-undefined = ζ is undefined at an end of the range
uncertainty-zeta-spans = ζ spans { $low }–{ $high }
uncertainty-describe-band = { $what }: { $zeta }; 5 % settling times (crosses) { $first }, { $second } and { $third }. { $ignored }
uncertainty-dist-normal = normal (tolerance = 3σ)
uncertainty-dist-uniform = uniform
uncertainty-spec-zeta = The spec window ζ { $low }–{ $high } is marked; { $share } of draws meet the whole spec.
uncertainty-spec-settling-time = The spec limit { $limit } is marked.
uncertainty-no-finite = No draw has a finite { $quantity }.
uncertainty-describe-histogram = Histogram of { $quantity } over { $draws } { $distribution } draws: from { $low } to { $high }, 5th percentile { $p5 }, 95th percentile { $p95 }.{ $marked ->
        [yes] {" "}{ $spec }
       *[no] {""}
    }
uncertainty-provisional-title = { $title } (provisional)
uncertainty-provisional-description = Provisional: from the first { $shown } draws while the run of { $full } continues. { $description }
uncertainty-axis-capacitor-voltage = capacitor voltage v_C
uncertainty-settling-band = 5 % settling band
uncertainty-axis-draws = draws
uncertainty-series-bins = draws per bin ({ $bins } bins)
uncertainty-no-finite-values = no finite values
uncertainty-spec-limit = spec limit
uncertainty-percentiles = 5th / 95th percentile

## The lecturers' guide (docs/embedding.md and docs/parameters.<tag>.md)

guide-parameters-heading = Parameters of every demo
guide-parameters-note = The URL parameters of every demo, for links and embeds (see the guide, docs/embedding.md). Generated from the Rust declarations and this language's catalogue; a test fails if this list and the code differ.
guide-column-key = key
guide-column-quantity = quantity
guide-column-unit = unit
guide-column-range = range
guide-column-default = default
guide-log = log
guide-readouts-plots = Readouts (`data-readout`): { $readouts }. Plots (`plots=`): { $plots }.
### design

design-map-title = { $metric ->
        [settling-time] Settling into ±{ $band } of x₀
        [peak-rebound] Peak rebound (% of x₀)
        [accel-rms] a_w (W_k)
       *[peak-transmissibility] Peak transmissibility |X/U|
    }: { $low } → { $high }
design-bar-label = { $metric ->
        [settling-time] settling time into ±{ $band } of x₀ [s]
        [peak-rebound] peak rebound [% of x₀]
        [accel-rms] a_w (W_k-weighted RMS) [m/s²]
       *[peak-transmissibility] peak transmissibility |X/U| [m/m]
    }{ $scale ->
        [log] , log scale
       *[linear] {""}
    }
design-axis-spring-rate = spring rate k
design-axis-damper-rate = damper rate c
design-axis-settling-time = settling time into ±{ $band } of x₀
design-axis-comfort = a_w (W_k-weighted RMS)
design-marker-selected = selected
design-marker-settled = settled
design-series-column = k = { $k }, c varied
design-series-pareto-front = Pareto front
design-series-band = settling band ±{ $band } of x₀
design-series-fastest = fastest on the grid
design-series-selected = selected design
design-road = an ISO 8608 class { $class } road at { $speed }
design-with-road = { $value } (class { $class } road, { $speed })
design-grid-size = { $n } × { $n } = { $cells }
design-grid-size-provisional = { $n } × { $n } = { $cells } ({ $full } × { $full } on the way)
design-map-lowest = lowest { $value } at k = { $k }, c = { $c }
design-map-no-cell = no cell is defined
design-map-selected-settles = selected design ζ = { $zeta } settles into ±{ $band } of x₀ in { $time }
design-map-selected-unsettled = selected design ζ = { $zeta } does not settle
design-map-no-selection = no valid design selected
design-describe-map = { $metric ->
        [settling-time] Settling time of the free response from x₀ = { $x0 } into ±{ $band } of x₀,
        [peak-rebound] Peak rebound of the free response from x₀ = { $x0 }, in % of x₀,
        [accel-rms] Comfort a_w (W_k-weighted RMS body acceleration) of the two-DOF car (wheel { $wheel }, tyre { $tyre }), stationary on { $road },
       *[peak-transmissibility] Peak transmissibility |X/U|
    } over k { $k_span } and c { $c_span } ({ $grid } × { $grid } grid, m = { $mass }): { $lowest }; { $selected }{ $outside ->
        [yes] {" "}(outside the map)
       *[no] {""}
    }. Colour from dark purple ({ $low }) to yellow ({ $high }){ $scale ->
        [log] {" "}on a logarithmic scale
       *[linear] {""}
    }. Dashed iso-ζ lines for ζ = { $z1 }, { $z2 }, { $z3 }, { $z4 } and { $z5 }; × marks the lowest cell, ● the selected design.
design-describe-pareto = Pareto front of { $count ->
        [one] { $count } non-dominated design
       *[other] { $count } non-dominated designs
    }: from the fastest, settling into ±{ $band } of x₀ in { $fast_time } with a_w = { $fast_accel }, to the smoothest, { $smooth_time } with a_w = { $smooth_accel }. { $selected } Comfort a_w: the W_k-weighted RMS body acceleration of the two-DOF car on { $road }.
design-pareto-selected = The selected design settles into ±{ $band } of x₀ in { $time } with a_w = { $accel }.
design-pareto-selected-unsettled = The selected design has no settling time.
design-pareto-empty = No design on the grid has both a settling time and a comfort value a_w.
design-describe-response = Selected design (ζ = { $zeta }) released from rest at x₀ = { $x0 } (a free response, not a step): rebounds { $rebound } of x₀ and stays within ±{ $band } of x₀ after { $time }.
design-describe-response-fastest = Selected design (ζ = { $zeta }) released from rest at x₀ = { $x0 } (a free response, not a step): rebounds { $rebound } of x₀ and stays within ±{ $band } of x₀ after { $time }; the fastest design on the grid (k = { $k }, c = { $c }) settles in { $fastest_time }.
design-response-unsettled = The selected design does not settle.
design-provisional = Provisional: from a coarse { $coarse } × { $coarse } grid while the { $full } × { $full } sweep runs. { $description }

## Declared strings (generated from the demo declarations)

### regimes

regimes-title = Damping regimes
regimes-summary = Free response from x(0) = x₀, x′(0) = v₀. The damping ratio ζ decides the regime: ζ = 0 undamped, 0 < ζ < 1 underdamped, ζ = 1 critically damped, ζ > 1 overdamped, ζ < 0 negatively damped (the response grows). The poles s = −ζωₙ ± ωₙ√(ζ² − 1) move around a circle of radius ωₙ, onto the real axis at ζ = 1 and across the imaginary axis at ζ = 0.
regimes-param-wn = natural frequency
regimes-param-zeta = damping ratio
regimes-param-x0 = initial displacement
regimes-param-v0 = initial velocity
regimes-readout-regime = regime
regimes-readout-wn = natural frequency ωₙ
regimes-readout-zeta = damping ratio ζ
regimes-readout-wd = damped frequency ω_d
regimes-readout-pole-re = pole real part
regimes-readout-pole-im = pole imaginary part
regimes-plot-response = Free response x(t)
regimes-plot-poles = Poles in the s-plane
regimes-preset-1 = Undamped ζ = 0
regimes-preset-2 = Underdamped ζ = 0.2
regimes-preset-3 = Critically damped ζ = 1
regimes-preset-4 = Overdamped ζ = 2
regimes-preset-5 = Negative damping ζ = −0.1
regimes-table-caption = The damping regimes
regimes-table-column-1 = regime
regimes-table-column-2 = condition
regimes-table-column-3 = roots s₁, s₂
regimes-table-column-4 = behaviour
regimes-table-column-5 = engineering examples
regimes-table-undamped-1 = Undamped
regimes-table-undamped-2 = ζ = 0
regimes-table-undamped-3 = ±iωₙ, on the imaginary axis
regimes-table-undamped-4 = oscillates forever at ωₙ
regimes-table-undamped-5 = ideal pendulum, LC tank circuit
regimes-table-underdamped-1 = Underdamped
regimes-table-underdamped-2 = 0 < ζ < 1
regimes-table-underdamped-3 = −ζωₙ ± iω_d, complex pair
regimes-table-underdamped-4 = decaying oscillation at ω_d
regimes-table-underdamped-5 = car suspension (ζ ≈ 0.2–0.7), guitar string
regimes-table-critically-damped-1 = Critically damped
regimes-table-critically-damped-2 = ζ = 1
regimes-table-critically-damped-3 = −ωₙ, double real root
regimes-table-critically-damped-4 = fastest return without oscillating
regimes-table-critically-damped-5 = door closer, analogue meter needle
regimes-table-overdamped-1 = Overdamped
regimes-table-overdamped-2 = ζ > 1
regimes-table-overdamped-3 = two negative real roots
regimes-table-overdamped-4 = slow return, no oscillation
regimes-table-overdamped-5 = heavy hydraulic damper, thermometer
regimes-table-negatively-damped-1 = Negatively damped
regimes-table-negatively-damped-2 = ζ < 0
regimes-table-negatively-damped-3 = right half-plane
regimes-table-negatively-damped-4 = growing oscillation
regimes-table-negatively-damped-5 = flutter (Tacoma Narrows), squealing brakes

### quarter-car

quarter-car-title = Quarter-car suspension
quarter-car-summary = One corner of a car: the body (sprung mass m) on a spring k and a damper c over a fixed road, pushed by x₀ and released from rest (x′(0) = 0). c and ζ are two views of one damper, c = 2ζ√(km): move either and the other follows; changing m or k keeps the damper, so ζ moves. The thin curves show the textbook settings on this car: comfort (ζ ≈ 0.3–0.4) rebounds, performance (ζ ≈ 0.65–0.7) settles fastest, critical (ζ = 1) and overdamped settings return without rebound but more slowly. Settling time jumps as ζ passes the values where a rebound drops inside the band: the fastest ζ sits just past such a jump, so a heavier load can push a well-tuned car over the edge (see the mass strip). Settling is measured on this free response: the settling time is the last time |x| equals band·|x₀|, after which the body stays within ±band·|x₀| of rest (not the band around the final value of a step response).
quarter-car-param-m = sprung mass
quarter-car-param-k = spring rate
quarter-car-param-c = damper rate
quarter-car-param-zeta = damping ratio
quarter-car-param-x0 = initial displacement
quarter-car-param-band = settling band around rest, relative to x₀
quarter-car-param-dm = sprung-mass variation
quarter-car-readout-regime = regime
quarter-car-readout-wn = natural frequency ωₙ
quarter-car-readout-fn = natural frequency fₙ
quarter-car-readout-zeta = damping ratio ζ
quarter-car-readout-c = damper rate c in use
quarter-car-readout-c-crit = critical damping 2√(km)
quarter-car-readout-wd = damped frequency ω_d
quarter-car-readout-settling-time = settling time t_s into ±band·|x₀| (free response)
quarter-car-readout-overshoot = peak rebound (of x₀)
quarter-car-readout-peak-time = time of peak rebound
quarter-car-readout-zeta-argmin = fastest-settling ζ (free response, same band)
quarter-car-readout-settling-min = its settling time
quarter-car-readout-zeta-lo = ζ at mass +dm %
quarter-car-readout-zeta-hi = ζ at mass −dm %
quarter-car-plot-response = Body displacement x(t)
quarter-car-plot-settling = Free-response settling time against ζ
quarter-car-plot-sensitivity = ζ when the sprung mass varies
quarter-car-preset-1 = Comfort ζ = 0.3
quarter-car-preset-2 = Comfort ζ = 0.4
quarter-car-preset-3 = Performance ζ = 0.65
quarter-car-preset-4 = Performance ζ = 0.7
quarter-car-preset-5 = Critical ζ = 1
quarter-car-preset-6 = Overdamped ζ = 2

### rlc

rlc-title = Series RLC circuit
rlc-summary = A capacitor charged to V₀ is switched into a loop with an inductor and a resistor at t = 0. Charge q obeys the same equation as a mass on a spring: L plays the mass, R the damper, 1/C the spring. With R below the critical resistance 2√(L/C) the energy sloshes between C and L and the current rings at ω_d, decaying as e^(−αt), α = R/(2L); at R = 2√(L/C) the capacitor empties fastest without reversing; above it the discharge is slower again. Q = 1/(2ζ) counts the ringing, and R/L is the half-power bandwidth of the current's resonance: driven by a sine voltage, |I|² stays above half its peak over a band exactly R/L rad/s wide, for any R. The current is negative while the capacitor discharges (i = dq/dt).
rlc-param-R = resistance
rlc-param-L = inductance
rlc-param-C = capacitance
rlc-param-V0 = initial capacitor voltage
rlc-readout-regime = regime
rlc-readout-w0 = resonant frequency ω₀ = 1/√(LC)
rlc-readout-f0 = resonant frequency f₀
rlc-readout-alpha = decay rate α = R/(2L)
rlc-readout-zeta = damping ratio ζ
rlc-readout-Q = quality factor Q = 1/(2ζ)
rlc-readout-bandwidth = current-resonance half-power bandwidth Δω = R/L
rlc-readout-R-crit = critical resistance 2√(L/C)
rlc-readout-wd = ringing frequency ω_d
rlc-readout-settling-time = v_C within 5 % of V₀ after
rlc-plot-current = Current i(t)
rlc-plot-voltage = Capacitor voltage v_C(t)
rlc-preset-1 = Lossless LC, R = 0
rlc-preset-2 = Ringing, R = 2 Ω
rlc-preset-3 = Underdamped, R = 5 Ω
rlc-preset-4 = Critical, R = 10 Ω
rlc-preset-5 = Overdamped, R = 20 Ω

### analogy

analogy-title = One equation, two machines
analogy-summary = A mass on a spring and damper and a series inductor–resistor–capacitor loop obey the same second-order equation. In the force–voltage analogy mass m ↔ inductance L, damping c ↔ resistance R, stiffness k ↔ 1/C, force F ↔ voltage E and displacement x ↔ charge q (so velocity ↔ current). Here the circuit is given the same numbers as the mechanism (L in H = m in kg, R in Ω = c in N·s/m, 1/C in 1/F = k in N/m, q₀ in C = x₀ in m), both released from rest: change any slider and both machines change together, their normalised responses stay one curve, and the energy swings between spring and mass exactly as between capacitor and inductor.
analogy-param-m = mass (≙ inductance L)
analogy-param-c = damping (≙ resistance R)
analogy-param-k = spring rate (≙ 1/C)
analogy-param-x0 = initial displacement (≙ charge q₀)
analogy-readout-m = mass m
analogy-readout-L = inductance L (≙ mass m)
analogy-readout-c = damping c
analogy-readout-R = resistance R (≙ damping c)
analogy-readout-k = spring rate k
analogy-readout-elastance = elastance 1/C (≙ k)
analogy-readout-compliance = compliance 1/k (≙ C)
analogy-readout-C = capacitance C (≙ 1/k)
analogy-readout-x0 = initial displacement x₀
analogy-readout-q0 = initial charge q₀ (≙ x₀)
analogy-readout-wn = natural frequency ωₙ = √(k/m)
analogy-readout-w0 = resonant frequency ω₀ = 1/√(LC) (≙ ωₙ)
analogy-readout-zeta = damping ratio ζ (both)
analogy-readout-regime = regime (both)
analogy-readout-Q = quality factor Q (both)
analogy-readout-energy = stored energy ½kx₀² = ½q₀²/C
analogy-plot-responses = Normalised responses of both machines
analogy-plot-energy = Energy exchange
analogy-preset-1 = Frictionless spring ↔ LC tank (c = R = 0)
analogy-preset-2 = Light damping ζ = 0.05
analogy-preset-3 = Critical ζ = 1 (c = 2√(mk), R = 2√(L/C))
analogy-preset-4 = Overdamped ζ = 2
analogy-preset-5 = Heavy and soft: m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF
analogy-table-caption = The force–voltage analogy: a·y″ + b·y′ + c·y = f(t) read two ways, with the values of both machines now
analogy-table-column-1 = role in the equation
analogy-table-column-2 = mechanical
analogy-table-column-3 = value now
analogy-table-column-4 = electrical
analogy-table-column-5 = value now
analogy-table-inertia-1 = inertia a
analogy-table-inertia-2 = mass m [kg]
analogy-table-inertia-4 = inductance L [H]
analogy-table-dissipation-1 = dissipation b
analogy-table-dissipation-2 = damping coefficient c [N·s/m]
analogy-table-dissipation-4 = resistance R [Ω]
analogy-table-stiffness-1 = stiffness c
analogy-table-stiffness-2 = spring rate k [N/m]
analogy-table-stiffness-4 = elastance 1/C [1/F]
analogy-table-compliance-1 = compliance 1/c
analogy-table-compliance-2 = compliance 1/k [m/N]
analogy-table-compliance-4 = capacitance C [F]
analogy-table-drive-1 = drive f(t)
analogy-table-drive-2 = force F [N]
analogy-table-drive-3 = 0: released from rest
analogy-table-drive-4 = voltage E [V]
analogy-table-drive-5 = 0: no source in the loop
analogy-table-coordinate-1 = coordinate y, initially y₀
analogy-table-coordinate-2 = displacement x, initially x₀ [m]
analogy-table-coordinate-4 = charge q, initially q₀ [C]
analogy-table-rate-1 = rate y′
analogy-table-rate-2 = velocity v = ẋ [m/s]
analogy-table-rate-3 = 0 at release
analogy-table-rate-4 = current i = q̇ [A]
analogy-table-rate-5 = 0 at release
analogy-table-natural-frequency-1 = natural frequency √(c/a)
analogy-table-natural-frequency-2 = ωₙ = √(k/m) [rad/s]
analogy-table-natural-frequency-4 = ω₀ = 1/√(LC) [rad/s]
analogy-table-damping-ratio-1 = damping ratio ζ = b/(2√(ac))
analogy-table-damping-ratio-2 = ζ = c/(2√(mk))
analogy-table-damping-ratio-4 = ζ = (R/2)·√(C/L)
analogy-table-quality-factor-1 = quality factor Q = √(ac)/b
analogy-table-quality-factor-2 = Q = √(mk)/c
analogy-table-quality-factor-4 = Q = √(L/C)/R
analogy-table-potential-energy-1 = stored by the stiffness
analogy-table-potential-energy-2 = spring ½kx², at release ½kx₀² [J]
analogy-table-potential-energy-4 = capacitor ½q²/C, at release ½q₀²/C [J]
analogy-table-kinetic-energy-1 = stored by the inertia
analogy-table-kinetic-energy-2 = mass ½mv² [J]
analogy-table-kinetic-energy-3 = 0 at release
analogy-table-kinetic-energy-4 = inductor ½Li² [J]
analogy-table-kinetic-energy-5 = 0 at release
analogy-table-power-lost-1 = dissipated power
analogy-table-power-lost-2 = damper c·v² [W]
analogy-table-power-lost-3 = 0 at release
analogy-table-power-lost-4 = resistor R·i² [W]
analogy-table-power-lost-5 = 0 at release

### universality

universality-title = One equation, many machines
universality-summary = Six machines, one equation a·y″ + b·y′ + c·y = f(t). Choose a machine for A and one for B and set each by its own physical parameters: each gives its own a, b and c, in its own units, and so a natural frequency ωₙ = √(c/a) and a damping ratio ζ = b/(2√(ac)). Released from y₀ at rest, a machine's normalised response y/y₀ against ωₙt depends on ζ alone, so machines with equal ζ draw one curve. Tick “match” and B's tuning parameters are solved so that its ωₙ and ζ equal A's: then B behaves exactly like A, second by second. The two-capacity thermal system never oscillates: b² − 4ac = (τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂) > 0, so its ζ > 1 whatever its capacities and resistances — heat has no inertia to carry it past equilibrium.
universality-param-A = machine A
universality-param-A-mass-spring = mass–spring–damper
universality-param-A-rlc = series RLC circuit
universality-param-A-u-tube = U-tube manometer
universality-param-A-servo = DC-motor position servo (PD control)
universality-param-A-storey = building storey under ground motion
universality-param-A-thermal = two-capacity thermal system
universality-param-A-m = mass
universality-param-A-c = damping coefficient
universality-param-A-k = spring rate
universality-param-A-L = inductance
universality-param-A-R = resistance
universality-param-A-C = capacitance
universality-param-A-len = liquid column length
universality-param-A-bore = tube bore
universality-param-A-rho = liquid density
universality-param-A-mu = dynamic viscosity
universality-param-A-J = inertia of motor and load
universality-param-A-Kt = motor torque constant
universality-param-A-Ra = armature resistance
universality-param-A-Kp = proportional gain
universality-param-A-Kd = derivative gain
universality-param-A-mf = floor mass
universality-param-A-h = storey height
universality-param-A-EI = bending stiffness of each of the 4 columns
universality-param-A-cf = storey damping coefficient
universality-param-A-C1 = heat capacity of body 1
universality-param-A-R1 = thermal resistance, body 1 to surroundings
universality-param-A-C2 = heat capacity of body 2
universality-param-A-R2 = thermal resistance, body 2 to body 1
universality-param-B = machine B
universality-param-B-mass-spring = mass–spring–damper
universality-param-B-rlc = series RLC circuit
universality-param-B-u-tube = U-tube manometer
universality-param-B-servo = DC-motor position servo (PD control)
universality-param-B-storey = building storey under ground motion
universality-param-B-thermal = two-capacity thermal system
universality-param-B-m = mass
universality-param-B-c = damping coefficient
universality-param-B-k = spring rate
universality-param-B-L = inductance
universality-param-B-R = resistance
universality-param-B-C = capacitance
universality-param-B-len = liquid column length
universality-param-B-bore = tube bore
universality-param-B-rho = liquid density
universality-param-B-mu = dynamic viscosity
universality-param-B-J = inertia of motor and load
universality-param-B-Kt = motor torque constant
universality-param-B-Ra = armature resistance
universality-param-B-Kp = proportional gain
universality-param-B-Kd = derivative gain
universality-param-B-mf = floor mass
universality-param-B-h = storey height
universality-param-B-EI = bending stiffness of each of the 4 columns
universality-param-B-cf = storey damping coefficient
universality-param-B-C1 = heat capacity of body 1
universality-param-B-R1 = thermal resistance, body 1 to surroundings
universality-param-B-C2 = heat capacity of body 2
universality-param-B-R2 = thermal resistance, body 2 to body 1
universality-param-match = match: tune B to behave like A (same ωₙ and ζ)
universality-readout-a-A = inertia coefficient a of A
universality-readout-b-A = damping coefficient b of A
universality-readout-c-A = stiffness coefficient c of A
universality-readout-wn-A = natural frequency ωₙ of A
universality-readout-zeta-A = damping ratio ζ of A
universality-readout-regime-A = regime of A
universality-readout-a-B = inertia coefficient a of B
universality-readout-b-B = damping coefficient b of B
universality-readout-c-B = stiffness coefficient c of B
universality-readout-wn-B = natural frequency ωₙ of B
universality-readout-zeta-B = damping ratio ζ of B
universality-readout-regime-B = regime of B
universality-readout-wn-ratio = time-scale ratio ωₙ(B)/ωₙ(A)
universality-readout-match = match
universality-plot-normalised = Normalised responses y/y₀ against ωₙt
universality-plot-realtime = Responses in real time
universality-preset-1 = Mass–spring and RLC circuit, matched
universality-preset-2 = U-tube manometer and mass–spring, matched
universality-preset-3 = Building storey tuned like a servo
universality-preset-4 = Thermometer (two capacities) and mass–spring, matched
universality-preset-5 = A thermal system cannot match an oscillator
universality-table-caption = One equation, many machines: what y, a, b and c are
universality-table-column-1 = machine
universality-table-column-2 = coordinate y
universality-table-column-3 = a
universality-table-column-4 = b
universality-table-column-5 = c
universality-table-column-6 = ωₙ
universality-table-column-7 = ζ
universality-table-mass-spring-1 = mass–spring–damper
universality-table-mass-spring-2 = displacement x [m]
universality-table-mass-spring-3 = mass m [kg]
universality-table-mass-spring-4 = damping coefficient c [N·s/m]
universality-table-mass-spring-5 = spring rate k [N/m]
universality-table-mass-spring-6 = √(k/m)
universality-table-mass-spring-7 = c/(2√(km))
universality-table-rlc-1 = series RLC circuit
universality-table-rlc-2 = charge q [C]
universality-table-rlc-3 = inductance L [H]
universality-table-rlc-4 = resistance R [Ω]
universality-table-rlc-5 = 1/C [1/F]
universality-table-rlc-6 = 1/√(LC)
universality-table-rlc-7 = (R/2)·√(C/L)
universality-table-u-tube-1 = U-tube manometer
universality-table-u-tube-2 = level change h [m]
universality-table-u-tube-3 = ρAL [kg]
universality-table-u-tube-4 = 8πμL [N·s/m]
universality-table-u-tube-5 = 2ρgA [N/m]
universality-table-u-tube-6 = √(2g/L)
universality-table-u-tube-7 = 16μ/(ρd²ωₙ)
universality-table-servo-1 = DC-motor position servo (PD control)
universality-table-servo-2 = angle error θ [rad]
universality-table-servo-3 = J [kg·m²]
universality-table-servo-4 = K_t(K_t + K_d)/R_a [N·m·s/rad]
universality-table-servo-5 = K_t·K_p/R_a [N·m/rad]
universality-table-servo-6 = √(K_t·K_p/(R_a·J))
universality-table-servo-7 = ≥ K_t²/(2ωₙR_a·J), the back-EMF alone
universality-table-storey-1 = building storey under ground motion
universality-table-storey-2 = storey drift u [m]
universality-table-storey-3 = floor mass m [kg]
universality-table-storey-4 = damping coefficient c [N·s/m]
universality-table-storey-5 = 12·4·EI/h³ [N/m]
universality-table-storey-6 = √(48EI/(m·h³))
universality-table-storey-7 = c/(2√(km))
universality-table-thermal-1 = two-capacity thermal system
universality-table-thermal-2 = temperature excess T₂ [K]
universality-table-thermal-3 = R₁C₁R₂C₂ [s²]
universality-table-thermal-4 = R₁C₁ + R₂C₂ + R₁C₂ [s]
universality-table-thermal-5 = 1
universality-table-thermal-6 = 1/√(τ₁τ₂)
universality-table-thermal-7 = (τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) > 1

### resonance

resonance-title = Forced resonance
resonance-summary = A 1 kg mass on a spring (k = ωₙ²·m) and damper (c = 2ζωₙ·m), at rest, is driven from t = 0 by F(t) = F₀·cos(ωt). In the steady state it moves at the drive frequency with amplitude |H(r)|·F₀/k, lagging the force by the phase of H, where r = ω/ωₙ. Light damping gives a tall, narrow peak near r = 1 (height ≈ Q = 1/(2ζ)). Its half-power width, r₂ − r₁ between the two frequency ratios where |H| = |H|max/√2, is ≈ 2ζ for light damping; above ζ ≈ 0.383 the lower point reaches r = 0 and the width is undefined, and above ζ = 1/√2 there is no peak at all. Driven exactly at resonance, the amplitude builds up over a few time constants 1/(ζωₙ) without beating; driven near it, the free and forced motions beat against each other until the free part dies away.
resonance-param-zeta = damping ratio
resonance-param-r = forcing ratio ω/ωₙ
resonance-param-wn = natural frequency
resonance-param-F0 = force amplitude
resonance-param-view = magnitude view
resonance-param-view-linear = linear |H|
resonance-param-view-db = decibels 20·log₁₀|H|
resonance-readout-peak-gain = resonant peak |H|max
resonance-readout-peak-ratio = peak at r = ω/ωₙ
resonance-readout-Q = quality factor Q = 1/(2ζ)
resonance-readout-peak-width = half-power width of the |H| peak r₂ − r₁ (ζ < 0.383)
resonance-readout-gain-at-r = gain |H(r)| at the drive
resonance-readout-phase-at-r = phase ∠H(r) at the drive
resonance-readout-amplitude = steady amplitude X = |H|·F₀/k
resonance-readout-beat-period = beat period 2π/|ω − ω_d| (while beats show)
resonance-readout-beats = beats in x(t)
resonance-plot-magnitude = Amplification |H(r)|
resonance-plot-phase = Phase ∠H(r)
resonance-plot-time = Response from rest x(t)
resonance-preset-1 = At resonance, ζ = 0.05
resonance-preset-2 = Beating near resonance, r = 0.9
resonance-preset-3 = No peak, ζ ≈ 1/√2
resonance-preset-4 = Quasi-static, r = 0.2
resonance-preset-5 = Isolation, r = 3

### integrators

integrators-title = Numerical integrators and their error
integrators-summary = The free oscillator integrated by forward Euler, symplectic Euler, Heun (RK2) and classical RK4 at a fixed step h, and by Dormand–Prince 5(4) with adaptive steps, each compared with the exact solution. A one-step method multiplies each mode by R(hλ) per step: when |R| > 1 the numbers grow no matter how well the method fits the equation, which is why forward Euler blows up a lightly damped oscillator unless h < 2ζ/ωₙ. When it is stable, halving h divides the error by 2^p, where p is the method's order: the convergence plot measures p. Switching a method off hides its curves; its readouts are still computed.
integrators-param-zeta = damping ratio
integrators-param-wn = natural frequency
integrators-param-h = step size
integrators-param-T = duration
integrators-param-x0 = initial displacement
integrators-param-tol = DP45 tolerance (relative; absolute tol·x₀)
integrators-param-euler = forward Euler
integrators-param-symplectic-euler = symplectic Euler
integrators-param-heun = Heun (RK2)
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4), adaptive
integrators-readout-max-err-euler = max error, forward Euler
integrators-readout-max-err-symplectic-euler = max error, symplectic Euler
integrators-readout-max-err-heun = max error, Heun
integrators-readout-max-err-rk4 = max error, RK4
integrators-readout-max-err-dp45 = max error, DP45
integrators-readout-order-euler = fitted order, forward Euler
integrators-readout-order-symplectic-euler = fitted order, symplectic Euler
integrators-readout-order-heun = fitted order, Heun
integrators-readout-order-rk4 = fitted order, RK4
integrators-readout-order-dp45 = observed order, DP45 (error against f-evaluations, where the tolerance sets the steps)
integrators-readout-stable-euler = stable at this h, forward Euler
integrators-readout-stable-symplectic-euler = stable at this h, symplectic Euler
integrators-readout-stable-heun = stable at this h, Heun
integrators-readout-stable-rk4 = stable at this h, RK4
integrators-readout-growth-euler = growth per step |R(hλ)|, forward Euler
integrators-readout-growth-symplectic-euler = growth per step (spectral radius), symplectic Euler
integrators-readout-growth-heun = growth per step |R(hλ)|, Heun
integrators-readout-growth-rk4 = growth per step |R(hλ)|, RK4
integrators-readout-steps-dp45 = DP45 accepted steps
integrators-readout-h-used = step used, every step but the last
integrators-readout-h-last = last step, ending the run at T
integrators-plot-response = Numerical solutions and the exact x(t)
integrators-plot-error = Error over time
integrators-plot-convergence = Convergence: max error against step h
integrators-plot-work = Work–precision: max error against f-evaluations
integrators-plot-stability = Stability regions and z = hλ
integrators-preset-1 = Lightly damped, h = 0.3 s
integrators-preset-2 = Euler just stable, h = 0.04 s
integrators-preset-3 = RK4 beyond its limit, h = 1.6 s
integrators-preset-4 = Undamped, h = 0.1 s
integrators-preset-5 = Stiff overdamped ζ = 2, ωₙ = 20
integrators-table-caption = The methods
integrators-table-column-1 = method
integrators-table-column-2 = order p
integrators-table-column-3 = f-evaluations per step
integrators-table-column-4 = amplification R(z)
integrators-table-column-5 = on an undamped oscillator
integrators-table-euler-1 = forward Euler
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = always grows: |R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = symplectic Euler
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = 2×2 matrix, not a scalar R
integrators-table-symplectic-euler-5 = bounded energy error while ωh ≤ 2
integrators-table-heun-1 = Heun (RK2)
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = slowly grows: |R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = classical RK4
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = slightly damps while ωh ≤ 2√2
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6 (first same as last)
integrators-table-dp45-4 = adaptive: h follows the error estimate
integrators-table-dp45-5 = stable: rejected steps shrink h

### flutter

flutter-title = Flutter: the Tacoma Narrows bridge
flutter-summary = A steady wind can feed a twisting bridge deck energy through its own motion. Scanlan wrote the wind's moment on a twisting deck with flutter derivatives measured in wind tunnels: A₂* multiplies the twist rate (a damping term) and A₃* the twist (a stiffness term), both functions of the reduced frequency K = Bω/U. The deck's damping ratio becomes ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I): for the bluff H-section of the 1940 Tacoma deck A₂* changes sign as the wind rises, and once it passes the threshold 4Iζ_s/(ρB⁴) any small twist grows at the deck's own torsional frequency (near 0.2 Hz) — flutter, not resonance: a steady wind has no frequency to match, the motion makes its own forcing. The frequency is found by iteration at each wind speed, since K depends on it. Linear theory lets the twist grow for ever; here the wind's damping term is assumed to halve at a twist θ_s, which bounds the motion in a large limit cycle, as on 7 November 1940, when in winds of about 42 mph the twist grew within the hour until the deck tore apart. Stated as such: the H-section's A₂* and A₃* are a teaching approximation, smooth curves shaped like the published wind-tunnel results (Scanlan & Tomko 1971; Billah & Scanlan 1991), not values read from them; I, ζ_s and θ_s are assumed. The streamlined box is idealised as a thin flat plate, whose A₂* and A₃* are exact in potential flow (Theodorsen 1935): its A₂* stays negative, so it never flutters in this range. The simplest picture ζ_eff = ζ_s − g·U is kept for comparison.
flutter-param-U = wind speed
flutter-param-model = model of the wind's moment
flutter-param-model-scanlan = flutter derivatives (Scanlan)
flutter-param-model-linear = simplest picture: ζ_eff = ζ_s − g·U
flutter-param-section = deck cross-section
flutter-param-section-h = 1940 H-section (plate girders)
flutter-param-section-box = streamlined box girder
flutter-param-B = deck width
flutter-param-I = mass moment of inertia per length (assumed for 1940)
flutter-param-f0 = torsional frequency in still air
flutter-param-zeta-s = structural damping ratio (assumed for 1940)
flutter-param-theta0 = initial twist
flutter-param-theta-s = twist at which the wind's damping halves (teaching assumption)
flutter-param-slope = simplest picture: damping lost per m/s
flutter-readout-regime = regime of a small twist
flutter-readout-U-crit = critical (flutter) speed U_crit, searched up to 100 m/s
flutter-readout-zeta-eff = effective damping ratio ζ_eff of a small twist
flutter-readout-growth-rate = growth rate σ of a small twist (< 0 decays)
flutter-readout-doubling-time = a small twist doubles every
flutter-readout-frequency = torsional frequency in the wind f
flutter-readout-K = reduced frequency K = Bω/U
flutter-readout-reduced-velocity = reduced velocity U/(f·B) = 2π/K
flutter-readout-A2 = flutter derivative A₂*(K)
flutter-readout-A3 = flutter derivative A₃*(K)
flutter-readout-limit-deg = limit-cycle twist amplitude (with the assumed bound θ_s)
flutter-readout-time-to-large = time from θ₀ to 90 % of the limit cycle
flutter-readout-amplitude-end-deg = twist amplitude at the end of the plot
flutter-plot-response = Deck twist θ(t) over minutes
flutter-plot-derivative = Flutter derivative A₂* and the flutter threshold
flutter-plot-damping = Effective damping against wind speed
flutter-plot-locus = Root locus as the wind rises
flutter-preset-1 = Tacoma 1940, 10 m/s (stable)
flutter-preset-2 = Tacoma 1940, 19 m/s (failure day, ≈ 42 mph)
flutter-preset-3 = Tacoma 1940, 30 m/s gale
flutter-preset-4 = Streamlined box deck, 19 m/s
flutter-preset-5 = Streamlined box deck, 40 m/s
flutter-preset-6 = Simplest picture, 19 m/s (ζ_eff = ζ_s − g·U)
flutter-table-caption = Flutter is not resonance
flutter-table-column-1 = case
flutter-table-column-2 = what drives it
flutter-table-column-3 = frequency
flutter-table-column-4 = damping
flutter-table-column-5 = amplitude
flutter-table-column-6 = cure
flutter-table-resonance-1 = Forced resonance (for contrast)
flutter-table-resonance-2 = an outside force oscillating near ωₙ (marching feet, an engine)
flutter-table-resonance-3 = set by the force; must match ωₙ
flutter-table-resonance-4 = positive: limits the peak to about 1/(2ζ) × static
flutter-table-resonance-5 = bounded steady state
flutter-table-resonance-6 = detune, or add damping
flutter-table-underdamped-1 = Wind below U_crit
flutter-table-underdamped-2 = steady wind; moment ∝ twist rate (A₂*) and twist (A₃*)
flutter-table-underdamped-3 = the deck's own, shifted a little by A₃*
flutter-table-underdamped-4 = ζ_eff > 0: A₂* below the threshold 4Iζ_s/(ρB⁴)
flutter-table-underdamped-5 = a twist dies away
flutter-table-underdamped-6 = —
flutter-table-undamped-1 = At U_crit
flutter-table-undamped-2 = steady wind; moment ∝ twist rate (A₂*) and twist (A₃*)
flutter-table-undamped-3 = the deck's own
flutter-table-undamped-4 = ζ_eff = 0: poles on the imaginary axis
flutter-table-undamped-5 = a twist persists unchanged
flutter-table-undamped-6 = —
flutter-table-negatively-damped-1 = Flutter, wind above U_crit
flutter-table-negatively-damped-2 = steady wind; the motion makes its own forcing
flutter-table-negatively-damped-3 = the deck's own, no matching needed
flutter-table-negatively-damped-4 = ζ_eff < 0: energy flows in every cycle
flutter-table-negatively-damped-5 = grows until the amplitude bound (or the deck) gives
flutter-table-negatively-damped-6 = a section whose A₂* stays negative: streamlined, open or stiffened deck

### nonlinear

nonlinear-title = Beyond the linear model
nonlinear-summary = A real suspension is only linear for small motions. Here the quarter car gets a cubic spring (k₃ > 0 hardening, k₃ < 0 softening), a damper that is stiffer in rebound (x′ > 0) than in compression, Coulomb friction in the joints and rubber bump stops beyond ±gap. Friction sticks and slips: while the mass slides it drags with the force F_c; once it stops, static friction holds it up to F_static, a set multiple of F_c, and it moves again only if the spring pulls harder. The motion is integrated with RK4, every stop located within its step, and drawn against the linear model m·x″ + c̄·x′ + k·x = 0 (c̄ the mean damper rate) from the same start. Watch where the prediction fails: the period depends on the amplitude (hardening shortens it, softening lengthens it), friction makes the amplitude fall in a straight line and then holds the mass off-centre for good (stick–slip), a bump stop turns a smooth swing into an impact, and an asymmetric damper shifts the mean position. The defaults are a plausible car corner: 300 kg, 24 kN/m (1.4 Hz), a 1 500 N·s/m damper (ζ ≈ 0.28) and a mildly progressive spring. x is the suspension extension from static equilibrium (positive = body up).
nonlinear-param-m = sprung mass
nonlinear-param-k = linear spring rate
nonlinear-param-k3 = cubic spring coefficient (+ hardening, − softening)
nonlinear-param-c-comp = damper rate in compression
nonlinear-param-c-reb = damper rate in rebound
nonlinear-param-friction = Coulomb friction force while sliding
nonlinear-param-stick-ratio = static-to-sliding friction ratio
nonlinear-param-gap = bump-stop clearance
nonlinear-param-k-stop = bump-stop rate (0 = no stops)
nonlinear-param-x0 = initial extension
nonlinear-param-v0 = initial velocity
nonlinear-readout-effect = dominant nonlinearity
nonlinear-readout-period-ratio = first-swing period ratio T_nonlinear / T_linear
nonlinear-readout-max-deviation = largest |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = nonlinear period of the first full swing (three zero crossings)
nonlinear-readout-period-linear = linear period of the first full swing (= 2π/ω_d)
nonlinear-readout-max-travel = largest |x| (nonlinear)
nonlinear-readout-stick-position = friction holds the mass at
nonlinear-plot-response = Nonlinear and linear response x(t)
nonlinear-plot-phase = Phase plane (x, v)
nonlinear-plot-spring = Spring and bump-stop force
nonlinear-plot-damper = Damper and friction force
nonlinear-preset-1 = Linear (all off)
nonlinear-preset-2 = Hardening spring
nonlinear-preset-3 = Softening spring
nonlinear-preset-4 = Friction stick–slip
nonlinear-preset-5 = Bump-stop impact
nonlinear-preset-6 = Asymmetric damper
nonlinear-table-caption = Where the linear model fails
nonlinear-table-column-1 = nonlinearity
nonlinear-table-column-2 = force law
nonlinear-table-column-3 = what the linear model misses
nonlinear-table-column-4 = signature in the plots
nonlinear-table-linear-1 = None (linear)
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = nothing: the model is exact
nonlinear-table-linear-4 = the two curves coincide
nonlinear-table-hardening-spring-1 = Hardening spring
nonlinear-table-hardening-spring-2 = k·x + k₃·x³, k₃ > 0
nonlinear-table-hardening-spring-3 = frequency rises with amplitude
nonlinear-table-hardening-spring-4 = shorter period while the swing is large; the curves drift apart
nonlinear-table-softening-spring-1 = Softening spring
nonlinear-table-softening-spring-2 = k·x + k₃·x³, k₃ < 0
nonlinear-table-softening-spring-3 = frequency falls with amplitude; past √(−k/k₃) the spring gives way
nonlinear-table-softening-spring-4 = longer period; a large start can escape
nonlinear-table-stick-slip-1 = Coulomb friction
nonlinear-table-stick-slip-2 = F_c·sgn(x′) sliding; up to F_static at rest
nonlinear-table-stick-slip-3 = amplitude falls by about 4F_c/k per cycle, in a straight line, then the mass sticks for good where |k·x| ≤ F_static
nonlinear-table-stick-slip-4 = straight-line envelope; a flat end off zero
nonlinear-table-bump-stop-impact-1 = Bump stops
nonlinear-table-bump-stop-impact-2 = k_stop·(|x| − gap) beyond ±gap
nonlinear-table-bump-stop-impact-3 = a sudden stiff contact: large force, fast reversal
nonlinear-table-bump-stop-impact-4 = clipped peaks at ±gap; kinks in the phase loop
nonlinear-table-asymmetric-damper-1 = Asymmetric damper
nonlinear-table-asymmetric-damper-2 = c_r·x′ in rebound, c_c·x′ in compression
nonlinear-table-asymmetric-damper-3 = a mean shift (jacking) and unequal half-cycles
nonlinear-table-asymmetric-damper-4 = lopsided decay; the phase spiral is off-centre
nonlinear-table-several-at-once-1 = Several at once
nonlinear-table-several-at-once-2 = sum of the above
nonlinear-table-several-at-once-3 = their effects add and interact
nonlinear-table-several-at-once-4 = see each row
nonlinear-table-escaped-1 = Softening spring past its limit
nonlinear-table-escaped-2 = k·x + k₃·x³ < 0 for |x| > √(−k/k₃)
nonlinear-table-escaped-3 = the model stops describing a suspension
nonlinear-table-escaped-4 = the run is cut where |x| exceeds 1 m

### quarter-car-2dof

quarter-car-2dof-title = Quarter car with body and wheel
quarter-car-2dof-summary = Two masses, two modes. The body (sprung mass m_s) sits on the suspension spring k_s and damper c_s; the wheel (unsprung mass m_u) sits on the tyre spring k_t, which follows the road u(t). Body bounce, around 1–1.5 Hz, is the body moving on the soft suspension; wheel hop, around 10–15 Hz, is the light wheel bouncing between the stiff tyre and the suspension. The frequency responses show both: the body follows slow road waves, rides over fast ones, and shakes most near body bounce; the tyre deflection, which decides grip, peaks at wheel hop. The tyre can only push: when the wheel rises above its static deflection the tyre force is zero and the wheel leaves the road until it lands again. Comfort is judged by the RMS body acceleration, road holding by the RMS tyre deflection, both over the run from rest, 0 … T. The response is exact between road samples, which are close enough to follow every bump and wheel hop. Displacements are from static equilibrium, upward positive; the random road sums 64 sinusoids with the ISO 8608 spectrum over 0.5–20 Hz. On it the page also shows the stationary RMS body acceleration on the full ISO 8608 road, unweighted and weighted by ISO 2631-1's W_k (a_w, the comfort measure), from the Lyapunov equation of the car.
quarter-car-2dof-param-ms = body (sprung) mass
quarter-car-2dof-param-mu = wheel (unsprung) mass
quarter-car-2dof-param-ks = suspension stiffness
quarter-car-2dof-param-kt = tyre stiffness
quarter-car-2dof-param-cs = suspension damping
quarter-car-2dof-param-road = road input
quarter-car-2dof-param-road-bump = single bump (1 − cos)
quarter-car-2dof-param-road-step = step (kerb)
quarter-car-2dof-param-road-sine = sinusoid
quarter-car-2dof-param-road-random = random road (ISO 8608)
quarter-car-2dof-param-h = bump or step height, sine amplitude
quarter-car-2dof-param-L = bump length
quarter-car-2dof-param-V = speed
quarter-car-2dof-param-f-road = sine road frequency
quarter-car-2dof-param-class = random road class
quarter-car-2dof-param-class-A = A (very good)
quarter-car-2dof-param-class-B = B (good)
quarter-car-2dof-param-class-C = C (average)
quarter-car-2dof-param-class-D = D (poor)
quarter-car-2dof-param-class-E = E (very poor)
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = random road seed
quarter-car-2dof-readout-f-body = body bounce frequency
quarter-car-2dof-readout-f-wheel = wheel hop frequency
quarter-car-2dof-readout-window = RMS window: the run from rest, 0 … T
quarter-car-2dof-readout-rms-body-accel = RMS body acceleration over 0 … T (comfort)
quarter-car-2dof-readout-rms-tyre-deflection = RMS tyre deflection z_u − u over 0 … T (road holding)
quarter-car-2dof-readout-max-travel = largest suspension travel |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = static tyre deflection (the wheel lifts off beyond it)
quarter-car-2dof-readout-lift-off = first lift-off: the tyre force reaches zero
quarter-car-2dof-readout-airborne-time = time the wheel is off the road
quarter-car-2dof-readout-rms-road = RMS road height (random road)
quarter-car-2dof-readout-stationary-accel = stationary RMS body acceleration, full ISO 8608 road (random road)
quarter-car-2dof-readout-stationary-weighted-accel = stationary a_w: RMS body acceleration weighted by ISO 2631-1 W_k (random road)
quarter-car-2dof-readout-body-gain = body / road amplitude at the sine frequency
quarter-car-2dof-readout-tyre-gain = tyre deflection / road amplitude at the sine frequency
quarter-car-2dof-plot-motion = Body, wheel and road
quarter-car-2dof-plot-accel = Body acceleration
quarter-car-2dof-plot-frf = Frequency response per unit road height
quarter-car-2dof-plot-tyre = Tyre deflection
quarter-car-2dof-preset-1 = Speed bump 5 cm at 10 m/s
quarter-car-2dof-preset-2 = Kerb step 5 cm
quarter-car-2dof-preset-3 = Road wave at body bounce
quarter-car-2dof-preset-4 = Road wave at wheel hop
quarter-car-2dof-preset-5 = Random road, class C, 20 m/s
quarter-car-2dof-preset-6 = Soft damper on a poor road

### design

design-title = Design space (k, c)
design-summary = Every cell of the map is one quarter car (sprung mass m on spring k and damper c), coloured by the chosen metric: settling time and peak rebound of the free response released from rest at x₀ = 60 mm (not a step response: the band and the rebound are relative to x₀), peak transmissibility, or ride comfort as ISO 2631-1 measures it: a_w, the RMS body acceleration weighted by the W_k filter (how much a seated person feels each frequency), stationary on a random ISO 8608 road at speed V. For comfort each cell is the two-DOF car (this body on the wheel m_u and tyre k_t set below, from the Lyapunov equation): the same numbers as the quarter-car-2dof demo for the same car; the readouts also give the unweighted RMS. Dashed lines join designs of equal damping ratio ζ = c/(2√(km)). The Pareto front holds the designs no other beats in both comfort and settling. Click the map (or a point of the front) to choose a design; move the mass to see the whole map shift.
design-param-m = sprung mass
design-param-mu = comfort: wheel (unsprung) mass
design-param-kt = comfort: tyre stiffness
design-param-metric = map metric
design-param-metric-settling-time = settling time (free response)
design-param-metric-peak-rebound = peak rebound (free response)
design-param-metric-accel-rms = comfort a_w (W_k-weighted RMS body acceleration)
design-param-metric-peak-transmissibility = peak transmissibility |X/U|
design-param-band = settling band, ± % of x₀ (free response)
design-param-road = road (ISO 8608)
design-param-road-a = class A (very good)
design-param-road-b = class B (good)
design-param-road-c = class C (average)
design-param-road-d = class D (poor)
design-param-V = comfort: speed
design-param-k-min = map: lowest spring rate
design-param-k-max = map: highest spring rate
design-param-c-min = map: lowest damper rate
design-param-c-max = map: highest damper rate
design-param-k = selected spring rate
design-param-c = selected damper rate
design-param-n = grid cells per axis
design-readout-zeta = damping ratio ζ
design-readout-settling-time = settling time into the ± band of x₀ (free response)
design-readout-overshoot = peak rebound, % of x₀ (free response)
design-readout-accel-rms = a_w: RMS body acceleration weighted by ISO 2631-1 W_k (two-DOF car, stationary on the ISO 8608 road at speed V)
design-readout-accel-unweighted = RMS body acceleration, unweighted (same car and road)
design-readout-k = selected spring rate k
design-readout-c = selected damper rate c
design-readout-grid-size = grid size (cells)
design-readout-compute-time = sweep compute time
design-plot-map = Metric over (k, c) with iso-ζ lines
design-plot-pareto = Comfort vs settling: Pareto front
design-plot-response = Selected design: free response x(t)
design-preset-1 = Settling-time map, 300 kg, ζ ≈ 0.37
design-preset-2 = Laden car 500 kg, same parts
design-preset-3 = Comfort map on a class C road
design-preset-4 = Peak-rebound map, ζ = 0.7 design
design-preset-5 = Fine grid 160 × 160

### uncertainty

uncertainty-title = Tolerance analysis
uncertainty-summary = Real parts are not their nominal values. Choose the system: the quarter car (sprung mass m, spring k and the damper set for ζ at nominal mass; the mass varies by ±dm as the car is loaded) or the series RLC loop (R, L and C each within ±dR, ±dL, ±dC). Only the chosen system's sliders are used; the other group is ignored. The exact ranges of ζ, ωₙ and Q come from the corners of the tolerance box. The Monte Carlo run draws N designs (seeded, so the same seed gives the same result): uniform within the tolerance, or normal with the tolerance as 3σ. The yield is the share of draws with ζ inside the spec window and a 5 % settling time (release from rest) no longer than the limit.
uncertainty-param-system = system
uncertainty-param-system-suspension = quarter-car suspension
uncertainty-param-system-rlc = series RLC
uncertainty-param-m = suspension: sprung mass
uncertainty-param-k = suspension: spring rate
uncertainty-param-zeta = suspension: design ζ at nominal mass
uncertainty-param-dm = suspension: mass tolerance ±
uncertainty-param-R = RLC: resistance
uncertainty-param-L = RLC: inductance
uncertainty-param-C = RLC: capacitance
uncertainty-param-dR = RLC: resistor tolerance ±
uncertainty-param-dL = RLC: inductor tolerance ±
uncertainty-param-dC = RLC: capacitor tolerance ±
uncertainty-param-dist = distribution of parts
uncertainty-param-dist-uniform = uniform within ±tolerance
uncertainty-param-dist-normal = normal, tolerance = 3σ
uncertainty-param-N = Monte Carlo draws
uncertainty-param-seed = random seed
uncertainty-param-zeta-lo = spec: lowest ζ
uncertainty-param-zeta-hi = spec: highest ζ
uncertainty-param-ts-max = spec: longest settling time
uncertainty-param-hist = second histogram
uncertainty-param-hist-zeta = damping ratio ζ
uncertainty-param-hist-f0 = natural frequency f0
uncertainty-param-hist-q = quality factor Q
uncertainty-param-hist-bandwidth = bandwidth
uncertainty-param-hist-settling-time = settling time
uncertainty-readout-zeta-min = ζ, lowest (exact)
uncertainty-readout-zeta-max = ζ, highest (exact)
uncertainty-readout-wn-min = ωₙ, lowest (exact)
uncertainty-readout-wn-max = ωₙ, highest (exact)
uncertainty-readout-Q-min = Q, lowest (exact)
uncertainty-readout-Q-max = Q, highest (exact)
uncertainty-readout-yield = yield (meets spec)
uncertainty-readout-zeta-p5 = ζ, 5th percentile
uncertainty-readout-zeta-p95 = ζ, 95th percentile
uncertainty-readout-Q-p5 = Q, 5th percentile
uncertainty-readout-Q-p95 = Q, 95th percentile
uncertainty-readout-draws = draws
uncertainty-readout-compute-time = Monte Carlo compute time
uncertainty-plot-band = Band of free responses over the tolerance
uncertainty-plot-zeta-hist = Monte Carlo: damping ratio ζ
uncertainty-plot-hist = Monte Carlo: chosen quantity
uncertainty-preset-1 = ζ = 1 design under ±10 % mass
uncertainty-preset-2 = ζ = 0.7 design under ±10 % mass
uncertainty-preset-3 = RLC 5 % parts
uncertainty-preset-4 = RLC 20 % parts

### paper

paper-title = The paper, checked
paper-summary = Zeta Lab was built from one paper on second-order differential equations in mechanical and electrical systems (Ihenacho, Samuel, Okechukwu et al., Science Publishing Group, 2026). Here is every figure and table of it, drawn live by the demo that reproduces it, and every number it states, checked: each claim shows the paper's value, the value the app computes, and a verdict. Follow a link to open the demo in exactly that state.
paper-readout-claims = claims checked
paper-readout-confirmed = claims confirmed
paper-readout-differs = claims that differ
paper-plot-fig1a = Figure 1(a)
paper-plot-fig1b = Figure 1(b)
paper-plot-fig2a = Figure 2(a)
paper-plot-fig2b = Figure 2(b)
paper-plot-fig3a = Figure 3(a)
paper-plot-fig3b = Figure 3(b)
paper-plot-fig4a = Figure 4(a)
paper-plot-fig4b = Figure 4(b)
paper-plot-fig5 = Figure 5
paper-plot-table1 = Table 1
paper-plot-table2 = Table 2
paper-plot-table3 = Table 3
