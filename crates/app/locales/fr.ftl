### rlc

rlc-axis-current = courant i
rlc-axis-voltage = tension du condensateur v_C
rlc-envelope = enveloppe
rlc-series-critical = R critique = { $resistance }
rlc-schematic = Circuit RLC série à t = { $time } : courant { $current }, condensateur à { $voltage }.
rlc-describe-current-undamped = R = { $resistance }, non amorti (circuit LC sans pertes) : le courant oscille indéfiniment à ω₀ = { $frequency }, entre ±{ $bound } (toute l'énergie passe dans la bobine et revient à chaque demi-période).
rlc-describe-voltage-undamped = R = { $resistance }, non amorti (circuit LC sans pertes) : la tension du condensateur oscille indéfiniment entre +{ $voltage } et −{ $voltage } à ω₀ = { $frequency }.
rlc-describe-current-underdamped = R = { $resistance }, inférieure à la résistance critique { $critical }, sous-amorti : le courant oscille à ω_d = { $frequency } (Q = { $q }) en décroissant comme e^(−αt), avec α = { $alpha } ; il ne dépasse jamais { $bound }.
rlc-describe-voltage-underdamped = R = { $resistance }, inférieure à la résistance critique { $critical }, sous-amorti : la tension du condensateur { $reversal ->
        [slight] ne s'inverse que légèrement (au plus { $rebound } de V₀, à l'intérieur de la bande)
        [count] { $crossings ->
            [one] change de signe une fois avant de s'établir
           *[other] change de signe { $crossings } fois avant de s'établir
        }
       *[never] ne change jamais de signe
    } et { $settles ->
        [yes] reste à moins de 5 % de V₀ après { $time }
       *[no] ne s'établit jamais
    }.
rlc-describe-current-critical = R = { $resistance }, égale à la résistance critique, amortissement critique : une seule impulsion de courant (négative, le condensateur se décharge) qui revient à zéro sans s'inverser ; le courant ne dépasse jamais { $bound }.
rlc-describe-voltage-critical = R = { $resistance }, égale à la résistance critique, amortissement critique : le condensateur se vide aussi vite que possible sans inversion ; sa tension { $settles ->
        [yes] reste à moins de 5 % de V₀ après { $time }
       *[no] ne s'établit jamais
    }.
rlc-describe-current-overdamped = R = { $resistance }, supérieure à la résistance critique { $critical }, suramorti : une seule impulsion lente de courant (négative, le condensateur se décharge), sans inversion, constante de temps lente { $time }.
rlc-describe-voltage-overdamped = R = { $resistance }, supérieure à la résistance critique { $critical }, suramorti : le condensateur se décharge lentement sans inversion ; sa tension { $settles ->
        [yes] reste à moins de 5 % de V₀ après { $time }
       *[no] ne s'établit jamais
    }.
rlc-title = Circuit RLC série
rlc-summary = Un condensateur chargé à V₀ est branché à t = 0 dans une boucle comprenant une bobine et une résistance. La charge q obéit à la même équation qu'une masse sur un ressort : L joue le rôle de la masse, R celui de l'amortisseur, 1/C celui du ressort. Avec R inférieure à la résistance critique 2√(L/C), l'énergie passe et repasse de C à L et le courant oscille à ω_d en décroissant comme e^(−αt), α = R/(2L) ; pour R = 2√(L/C), le condensateur se vide le plus vite possible sans inversion ; au-delà, la décharge redevient plus lente. Q = 1/(2ζ) mesure l'importance des oscillations, et R/L est la bande passante à demi-puissance de la résonance du courant : sous une tension sinusoïdale, |I|² reste au-dessus de la moitié de son maximum sur une bande large d'exactement R/L rad/s, quel que soit R. Le courant est négatif pendant que le condensateur se décharge (i = dq/dt).
rlc-param-R = résistance
rlc-param-L = inductance
rlc-param-C = capacité
rlc-param-V0 = tension initiale du condensateur
rlc-readout-regime = régime
rlc-readout-w0 = pulsation de résonance ω₀ = 1/√(LC)
rlc-readout-f0 = fréquence de résonance f₀
rlc-readout-alpha = taux de décroissance α = R/(2L)
rlc-readout-zeta = taux d'amortissement ζ
rlc-readout-Q = facteur de qualité Q = 1/(2ζ)
rlc-readout-bandwidth = bande passante à demi-puissance de la résonance en courant Δω = R/L
rlc-readout-R-crit = résistance critique 2√(L/C)
rlc-readout-wd = pulsation des oscillations ω_d
rlc-readout-settling-time = v_C à moins de 5 % de V₀ après
rlc-plot-current = Courant i(t)
rlc-plot-voltage = Tension du condensateur v_C(t)
rlc-preset-1 = LC sans pertes, R = 0
rlc-preset-2 = Oscillant, R = 2 Ω
rlc-preset-3 = Sous-amorti, R = 5 Ω
rlc-preset-4 = Critique, R = 10 Ω
rlc-preset-5 = Suramorti, R = 20 Ω

### analogy

analogy-axis-response = réponse normalisée
analogy-axis-energy = énergie
analogy-series-x = x/x₀ masse
analogy-series-q = q/q₀ circuit
analogy-series-v = v/(x₀ωₙ) masse
analogy-series-i = i/(q₀ω₀) circuit
analogy-series-spring = ½kx² ressort
analogy-series-capacitor = ½q²/C condensateur
analogy-series-mass = ½mv² masse
analogy-series-inductor = ½Li² bobine
analogy-series-total-mass = total, masse
analogy-series-total-circuit = total, circuit
analogy-caption-mechanical = mécanique
analogy-caption-electrical = électrique
analogy-schematic-title = Jumeaux mécanique et électrique
analogy-describe-responses = { $regime } (ζ = { $zeta }) : le rapport mécanique x/x₀ et le rapport électrique q/q₀ coïncident, de même que la vitesse v/(x₀ωₙ) et le courant i/(q₀ω₀) ({ $same ->
        [exact] identiques jusqu'au dernier chiffre
       *[close] écart maximal { $difference }
    }) ; { $motion ->
        [decaying] les deux oscillent à ω_d = { $frequency } et décroissent avec la constante de temps 1/(ζωₙ) = { $time }
        [lasting] les deux oscillent indéfiniment à ω₀ = ωₙ = { $frequency }
       *[creeping] les deux reviennent lentement au repos sans osciller
    }.
analogy-describe-energy = À t = 0, toute l'énergie, { $energy }, est stockée dans le ressort, et de même dans le condensateur. { $exchange ->
        [swings] Elle passe dans la masse (la bobine), au plus { $peak } à la fois, puis revient, deux fois par cycle
       *[passes] Sans oscillation, au plus { $peak } transite par la masse (la bobine)
    } ; { $loss ->
        [none] sans amortisseur (résistance), elle est encore entièrement présente après { $time }
       *[heat] l'amortisseur c (la résistance R) la transforme en chaleur ; il en reste { $left } ({ $percent }) après { $time }
    }. Les courbes mécaniques et électriques coïncident.
analogy-schematic = À t = { $time } : la masse est déplacée de { $displacement } et se déplace à { $velocity } ; le condensateur porte { $charge } et le courant vaut { $current }. Les mêmes nombres, dans d'autres unités.
analogy-title = Une équation, deux machines
analogy-summary = Une masse sur un ressort et un amortisseur et une boucle série bobine–résistance–condensateur obéissent à la même équation du second ordre. Dans l'analogie force–tension, masse m ↔ inductance L, amortissement c ↔ résistance R, raideur k ↔ 1/C, force F ↔ tension E et déplacement x ↔ charge q (donc vitesse ↔ courant). Ici, le circuit reçoit les mêmes nombres que le mécanisme (L en H = m en kg, R en Ω = c en N·s/m, 1/C en 1/F = k en N/m, q₀ en C = x₀ en m), et tous deux partent du repos : déplacez n'importe quel curseur et les deux machines changent ensemble, leurs réponses normalisées restent une seule et même courbe, et l'énergie passe du ressort à la masse exactement comme du condensateur à la bobine.
analogy-param-m = masse (≙ inductance L)
analogy-param-c = amortissement (≙ résistance R)
analogy-param-k = raideur du ressort (≙ 1/C)
analogy-param-x0 = déplacement initial (≙ charge q₀)
analogy-readout-m = masse m
analogy-readout-L = inductance L (≙ masse m)
analogy-readout-c = amortissement c
analogy-readout-R = résistance R (≙ amortissement c)
analogy-readout-k = raideur du ressort k
analogy-readout-elastance = élastance 1/C (≙ k)
analogy-readout-compliance = souplesse 1/k (≙ C)
analogy-readout-C = capacité C (≙ 1/k)
analogy-readout-x0 = déplacement initial x₀
analogy-readout-q0 = charge initiale q₀ (≙ x₀)
analogy-readout-wn = pulsation propre ωₙ = √(k/m)
analogy-readout-w0 = pulsation de résonance ω₀ = 1/√(LC) (≙ ωₙ)
analogy-readout-zeta = taux d'amortissement ζ (les deux)
analogy-readout-regime = régime (les deux)
analogy-readout-Q = facteur de qualité Q (les deux)
analogy-readout-energy = énergie stockée ½kx₀² = ½q₀²/C
analogy-plot-responses = Réponses normalisées des deux machines
analogy-plot-energy = Échange d'énergie
analogy-preset-1 = Ressort sans frottement ↔ circuit oscillant LC (c = R = 0)
analogy-preset-2 = Amortissement faible ζ = 0,05
analogy-preset-3 = Critique ζ = 1 (c = 2√(mk), R = 2√(L/C))
analogy-preset-4 = Suramorti ζ = 2
analogy-preset-5 = Lourd et souple : m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF
analogy-table-caption = L'analogie force–tension : a·y″ + b·y′ + c·y = f(t) lue de deux façons, avec les valeurs actuelles des deux machines
analogy-table-column-1 = rôle dans l'équation
analogy-table-column-2 = mécanique
analogy-table-column-3 = valeur actuelle
analogy-table-column-4 = électrique
analogy-table-column-5 = valeur actuelle
analogy-table-inertia-1 = inertie a
analogy-table-inertia-2 = masse m [kg]
analogy-table-inertia-4 = inductance L [H]
analogy-table-dissipation-1 = dissipation b
analogy-table-dissipation-2 = coefficient d'amortissement c [N·s/m]
analogy-table-dissipation-4 = résistance R [Ω]
analogy-table-stiffness-1 = raideur c
analogy-table-stiffness-2 = raideur du ressort k [N/m]
analogy-table-stiffness-4 = élastance 1/C [1/F]
analogy-table-compliance-1 = souplesse 1/c
analogy-table-compliance-2 = souplesse 1/k [m/N]
analogy-table-compliance-4 = capacité C [F]
analogy-table-drive-1 = excitation f(t)
analogy-table-drive-2 = force F [N]
analogy-table-drive-3 = 0 : lâché depuis le repos
analogy-table-drive-4 = tension E [V]
analogy-table-drive-5 = 0 : aucune source dans la boucle
analogy-table-coordinate-1 = coordonnée y, initialement y₀
analogy-table-coordinate-2 = déplacement x, initialement x₀ [m]
analogy-table-coordinate-4 = charge q, initialement q₀ [C]
analogy-table-rate-1 = dérivée y′
analogy-table-rate-2 = vitesse v = ẋ [m/s]
analogy-table-rate-3 = 0 au lâcher
analogy-table-rate-4 = courant i = q̇ [A]
analogy-table-rate-5 = 0 au lâcher
analogy-table-natural-frequency-1 = pulsation propre √(c/a)
analogy-table-natural-frequency-2 = ωₙ = √(k/m) [rad/s]
analogy-table-natural-frequency-4 = ω₀ = 1/√(LC) [rad/s]
analogy-table-damping-ratio-1 = taux d'amortissement ζ = b/(2√(ac))
analogy-table-damping-ratio-2 = ζ = c/(2√(mk))
analogy-table-damping-ratio-4 = ζ = (R/2)·√(C/L)
analogy-table-quality-factor-1 = facteur de qualité Q = √(ac)/b
analogy-table-quality-factor-2 = Q = √(mk)/c
analogy-table-quality-factor-4 = Q = √(L/C)/R
analogy-table-potential-energy-1 = stockée par la raideur
analogy-table-potential-energy-2 = ressort ½kx², au lâcher ½kx₀² [J]
analogy-table-potential-energy-4 = condensateur ½q²/C, au lâcher ½q₀²/C [J]
analogy-table-kinetic-energy-1 = stockée par l'inertie
analogy-table-kinetic-energy-2 = masse ½mv² [J]
analogy-table-kinetic-energy-3 = 0 au lâcher
analogy-table-kinetic-energy-4 = bobine ½Li² [J]
analogy-table-kinetic-energy-5 = 0 au lâcher
analogy-table-power-lost-1 = puissance dissipée
analogy-table-power-lost-2 = amortisseur c·v² [W]
analogy-table-power-lost-3 = 0 au lâcher
analogy-table-power-lost-4 = résistance R·i² [W]
analogy-table-power-lost-5 = 0 au lâcher

