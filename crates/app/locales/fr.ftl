## Schémas

schematic-title = Schéma
schematic-circuit = Circuit
### rlc

rlc-axis-current = courant i
rlc-axis-voltage = tension du condensateur v_C
rlc-envelope = enveloppe
rlc-series-critical = R critique = { $resistance }
rlc-schematic = Circuit RLC série à t = { $time } : courant { $current }, condensateur à { $voltage }.
rlc-describe-current = { $regime ->
        [undamped] R = { $resistance }, non amorti (circuit LC sans pertes) : le courant oscille indéfiniment à ω₀ = { $frequency }, entre ±{ $bound } (toute l'énergie passe dans la bobine et revient à chaque demi-période).
        [underdamped] R = { $resistance }, inférieure à la résistance critique { $critical }, sous-amorti : le courant oscille à ω_d = { $ringing } (Q = { $q }) en décroissant comme e^(−αt), avec α = { $alpha } ; il ne dépasse jamais { $bound }.
        [critical] R = { $resistance }, égale à la résistance critique, amortissement critique : une seule impulsion de courant (négative, le condensateur se décharge) qui revient à zéro sans s'inverser ; le courant ne dépasse jamais { $bound }.
       *[overdamped] R = { $resistance }, supérieure à la résistance critique { $critical }, suramorti : une seule impulsion lente de courant (négative, le condensateur se décharge), sans inversion, constante de temps lente { $time }.
    }
rlc-describe-voltage = { $regime ->
        [undamped] R = { $resistance }, non amorti (circuit LC sans pertes) : la tension du condensateur oscille indéfiniment entre +{ $voltage } et −{ $voltage } à ω₀ = { $frequency }.
        [underdamped] R = { $resistance }, inférieure à la résistance critique { $critical }, sous-amorti : la tension du condensateur { $reversal ->
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
        [critical] R = { $resistance }, égale à la résistance critique, amortissement critique : le condensateur se vide aussi vite que possible sans inversion ; sa tension { $settles ->
            [yes] reste à moins de 5 % de V₀ après { $time }
           *[no] ne s'établit jamais
        }.
       *[overdamped] R = { $resistance }, supérieure à la résistance critique { $critical }, suramorti : le condensateur se décharge lentement sans inversion ; sa tension { $settles ->
            [yes] reste à moins de 5 % de V₀ après { $time }
           *[no] ne s'établit jamais
        }.
    }
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

### universality

universality-axis-response = réponse normalisée y/y₀
universality-axis-time = temps normalisé ωₙt
universality-series-critical = ζ = 1 (critique), pour référence
universality-schematic-title = Machines A et B
universality-match-off = désactivé
universality-match-on = activé : B a les mêmes ωₙ et ζ que A
universality-match-too-light = inaccessible : ses autres paramètres étant conservés, B ne peut pas descendre sous ζ = { $zeta_min } ; A a ζ = { $zeta }
universality-match-out-of-range = inaccessible avec les curseurs : B nécessiterait { $symbol } = { $value }, hors de { $low } … { $high }
universality-match-impossible = inaccessible : A n'a pas de pulsation propre
universality-describe-normalised = Lâchées depuis le repos : A ({ $machine_a }, ζ = { $zeta_a }) { $behaviour_a ->
        [forever] oscille indéfiniment
        [dies-away] oscille en s'amortissant
        [fastest] revient aussi vite que possible sans dépassement
       *[creeps] revient lentement sans dépassement
    } ; B ({ $machine_b }, ζ = { $zeta_b }) { $behaviour_b ->
        [forever] oscille indéfiniment
        [dies-away] oscille en s'amortissant
        [fastest] revient aussi vite que possible sans dépassement
       *[creeps] revient lentement sans dépassement
    }. { $relation ->
        [coincide] Les deux courbes coïncident (écart maximal { $gap }).
       *[differ] Les courbes diffèrent d'au plus { $gap } de y₀.
    }{ $thermal ->
        [yes] { " " }Un système thermique à deux capacités ne peut pas osciller : son ζ dépasse 1 quelles que soient ses capacités et ses résistances.
       *[no] { "" }
    }
universality-describe-realtime = Temps réel sur { $window } : échelle de temps 1/ωₙ de A { $scale_a }, de B { $scale_b } ; { $pace ->
        [faster] B va { $factor } fois plus vite que A
        [slower] B va { $factor } fois plus lentement que A
       *[same] B suit exactement le rythme de A
    }.
universality-schematic = À t = { $time } : A, { $machine_a } : { $coordinate_a } = { $value_a } ; B, { $machine_b } : { $coordinate_b } = { $value_b }.
universality-title = Une équation, de nombreuses machines
universality-summary = Six machines, une équation a·y″ + b·y′ + c·y = f(t). Choisissez une machine pour A et une pour B, et réglez chacune par ses propres paramètres physiques : chacune donne ses propres a, b et c, dans ses propres unités, et donc une pulsation propre ωₙ = √(c/a) et un taux d'amortissement ζ = b/(2√(ac)). Lâchée depuis y₀ au repos, la réponse normalisée y/y₀ d'une machine en fonction de ωₙt ne dépend que de ζ : des machines de même ζ tracent une seule et même courbe. Cochez « accorder » et les paramètres de réglage de B sont calculés pour que ses ωₙ et ζ égalent ceux de A : B se comporte alors exactement comme A, seconde par seconde. Le système thermique à deux capacités n'oscille jamais : b² − 4ac = (τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂) > 0, donc son ζ > 1 quelles que soient ses capacités et ses résistances — la chaleur n'a pas d'inertie qui l'emporterait au-delà de l'équilibre.
universality-param-A = machine A
universality-param-A-mass-spring = masse–ressort–amortisseur
universality-param-A-rlc = circuit RLC série
universality-param-A-u-tube = manomètre à tube en U
universality-param-A-servo = asservissement de position par moteur à courant continu (commande PD)
universality-param-A-storey = étage de bâtiment soumis à un mouvement du sol
universality-param-A-thermal = système thermique à deux capacités
universality-param-A-m = masse
universality-param-A-c = coefficient d'amortissement
universality-param-A-k = raideur du ressort
universality-param-A-L = inductance
universality-param-A-R = résistance
universality-param-A-C = capacité
universality-param-A-len = longueur de la colonne de liquide
universality-param-A-bore = diamètre intérieur du tube
universality-param-A-rho = masse volumique du liquide
universality-param-A-mu = viscosité dynamique
universality-param-A-J = inertie du moteur et de la charge
universality-param-A-Kt = constante de couple du moteur
universality-param-A-Ra = résistance d'induit
universality-param-A-Kp = gain proportionnel
universality-param-A-Kd = gain dérivé
universality-param-A-mf = masse du plancher
universality-param-A-h = hauteur d'étage
universality-param-A-EI = rigidité en flexion de chacun des 4 poteaux
universality-param-A-cf = coefficient d'amortissement de l'étage
universality-param-A-C1 = capacité thermique du corps 1
universality-param-A-R1 = résistance thermique, du corps 1 vers l'ambiance
universality-param-A-C2 = capacité thermique du corps 2
universality-param-A-R2 = résistance thermique, du corps 2 vers le corps 1
universality-param-B = machine B
universality-param-B-mass-spring = masse–ressort–amortisseur
universality-param-B-rlc = circuit RLC série
universality-param-B-u-tube = manomètre à tube en U
universality-param-B-servo = asservissement de position par moteur à courant continu (commande PD)
universality-param-B-storey = étage de bâtiment soumis à un mouvement du sol
universality-param-B-thermal = système thermique à deux capacités
universality-param-B-m = masse
universality-param-B-c = coefficient d'amortissement
universality-param-B-k = raideur du ressort
universality-param-B-L = inductance
universality-param-B-R = résistance
universality-param-B-C = capacité
universality-param-B-len = longueur de la colonne de liquide
universality-param-B-bore = diamètre intérieur du tube
universality-param-B-rho = masse volumique du liquide
universality-param-B-mu = viscosité dynamique
universality-param-B-J = inertie du moteur et de la charge
universality-param-B-Kt = constante de couple du moteur
universality-param-B-Ra = résistance d'induit
universality-param-B-Kp = gain proportionnel
universality-param-B-Kd = gain dérivé
universality-param-B-mf = masse du plancher
universality-param-B-h = hauteur d'étage
universality-param-B-EI = rigidité en flexion de chacun des 4 poteaux
universality-param-B-cf = coefficient d'amortissement de l'étage
universality-param-B-C1 = capacité thermique du corps 1
universality-param-B-R1 = résistance thermique, du corps 1 vers l'ambiance
universality-param-B-C2 = capacité thermique du corps 2
universality-param-B-R2 = résistance thermique, du corps 2 vers le corps 1
universality-param-match = accorder : régler B pour qu'il se comporte comme A (mêmes ωₙ et ζ)
universality-readout-a-A = coefficient d'inertie a de A
universality-readout-b-A = coefficient d'amortissement b de A
universality-readout-c-A = coefficient de raideur c de A
universality-readout-wn-A = pulsation propre ωₙ de A
universality-readout-zeta-A = taux d'amortissement ζ de A
universality-readout-regime-A = régime de A
universality-readout-a-B = coefficient d'inertie a de B
universality-readout-b-B = coefficient d'amortissement b de B
universality-readout-c-B = coefficient de raideur c de B
universality-readout-wn-B = pulsation propre ωₙ de B
universality-readout-zeta-B = taux d'amortissement ζ de B
universality-readout-regime-B = régime de B
universality-readout-wn-ratio = rapport des échelles de temps ωₙ(B)/ωₙ(A)
universality-readout-match = accord
universality-plot-normalised = Réponses normalisées y/y₀ en fonction de ωₙt
universality-plot-realtime = Réponses en temps réel
universality-preset-1 = Masse–ressort et circuit RLC, accordés
universality-preset-2 = Manomètre à tube en U et masse–ressort, accordés
universality-preset-3 = Étage de bâtiment réglé comme un asservissement
universality-preset-4 = Thermomètre (deux capacités) et masse–ressort, accordés
universality-preset-5 = Un système thermique ne peut pas imiter un oscillateur
universality-table-caption = Une équation, de nombreuses machines : ce que sont y, a, b et c
universality-table-column-1 = machine
universality-table-column-2 = coordonnée y
universality-table-column-3 = a
universality-table-column-4 = b
universality-table-column-5 = c
universality-table-column-6 = ωₙ
universality-table-column-7 = ζ
universality-table-mass-spring-1 = masse–ressort–amortisseur
universality-table-mass-spring-2 = déplacement x [m]
universality-table-mass-spring-3 = masse m [kg]
universality-table-mass-spring-4 = coefficient d'amortissement c [N·s/m]
universality-table-mass-spring-5 = raideur du ressort k [N/m]
universality-table-mass-spring-6 = √(k/m)
universality-table-mass-spring-7 = c/(2√(km))
universality-table-rlc-1 = circuit RLC série
universality-table-rlc-2 = charge q [C]
universality-table-rlc-3 = inductance L [H]
universality-table-rlc-4 = résistance R [Ω]
universality-table-rlc-5 = 1/C [1/F]
universality-table-rlc-6 = 1/√(LC)
universality-table-rlc-7 = (R/2)·√(C/L)
universality-table-u-tube-1 = manomètre à tube en U
universality-table-u-tube-2 = variation de niveau h [m]
universality-table-u-tube-3 = ρAL [kg]
universality-table-u-tube-4 = 8πμL [N·s/m]
universality-table-u-tube-5 = 2ρgA [N/m]
universality-table-u-tube-6 = √(2g/L)
universality-table-u-tube-7 = 16μ/(ρd²ωₙ)
universality-table-servo-1 = asservissement de position par moteur à courant continu (commande PD)
universality-table-servo-2 = erreur angulaire θ [rad]
universality-table-servo-3 = J [kg·m²]
universality-table-servo-4 = K_t(K_t + K_d)/R_a [N·m·s/rad]
universality-table-servo-5 = K_t·K_p/R_a [N·m/rad]
universality-table-servo-6 = √(K_t·K_p/(R_a·J))
universality-table-servo-7 = ≥ K_t²/(2ωₙR_a·J), due à la seule force contre-électromotrice
universality-table-storey-1 = étage de bâtiment soumis à un mouvement du sol
universality-table-storey-2 = déplacement relatif de l'étage u [m]
universality-table-storey-3 = masse du plancher m [kg]
universality-table-storey-4 = coefficient d'amortissement c [N·s/m]
universality-table-storey-5 = 12·4·EI/h³ [N/m]
universality-table-storey-6 = √(48EI/(m·h³))
universality-table-storey-7 = c/(2√(km))
universality-table-thermal-1 = système thermique à deux capacités
universality-table-thermal-2 = excès de température T₂ [K]
universality-table-thermal-3 = R₁C₁R₂C₂ [s²]
universality-table-thermal-4 = R₁C₁ + R₂C₂ + R₁C₂ [s]
universality-table-thermal-5 = 1
universality-table-thermal-6 = 1/√(τ₁τ₂)
universality-table-thermal-7 = (τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) > 1

### regimes

regimes-envelope = enveloppe ±A·e^(−ζωₙt)
regimes-series-response = x(t), { $regime }
regimes-describe-settles = { $regime } : { $swings ->
        [0] ne franchit pas l'équilibre avant de s'établir
        [one] franchit l'équilibre une fois avant de s'établir
       *[other] franchit l'équilibre { $swings } fois avant de s'établir
    }, reste à moins de 5 % du repos après { $time }, rebond maximal { $rebound }.
regimes-describe-unsettled = { $regime } : { $swings ->
        [0] ne franchit pas l'équilibre avant de s'établir
        [one] franchit l'équilibre une fois avant de s'établir
       *[other] franchit l'équilibre { $swings } fois avant de s'établir
    }, ne s'établit pas, rebond maximal { $rebound }.
regimes-describe-undamped = non amorti : oscille indéfiniment avec une amplitude de { $amplitude } à { $frequency }.
regimes-describe-growing = amortissement négatif : la réponse croît sans limite, d'un facteur e toutes les { $time }.
regimes-describe-at-rest = { $regime } : part du repos à l'équilibre.
regimes-poles = Pôles en { $re1 } { $sign1 } { $im1 }i et { $re2 } { $sign2 } { $im2 }i 1/s, dans le demi-plan { $side ->
        [right] droit (instable)
       *[left] gauche (stable)
    }.
regimes-schematic = Masse sur ressort et amortisseur à t = { $time } : déplacée de { $displacement } par rapport au repos.
regimes-title = Régimes d'amortissement
regimes-summary = Réponse libre depuis x(0) = x₀, x′(0) = v₀. Le taux d'amortissement ζ détermine le régime : ζ = 0 non amorti, 0 < ζ < 1 sous-amorti, ζ = 1 amortissement critique, ζ > 1 suramorti, ζ < 0 amortissement négatif (la réponse croît). Les pôles s = −ζωₙ ± ωₙ√(ζ² − 1) se déplacent sur un cercle de rayon ωₙ, rejoignent l'axe réel en ζ = 1 et traversent l'axe imaginaire en ζ = 0.
regimes-param-wn = pulsation propre
regimes-param-zeta = taux d'amortissement
regimes-param-x0 = déplacement initial
regimes-param-v0 = vitesse initiale
regimes-readout-regime = régime
regimes-readout-wn = pulsation propre ωₙ
regimes-readout-zeta = taux d'amortissement ζ
regimes-readout-wd = pulsation amortie ω_d
regimes-readout-pole-re = partie réelle du pôle
regimes-readout-pole-im = partie imaginaire du pôle
regimes-plot-response = Réponse libre x(t)
regimes-plot-poles = Pôles dans le plan s
regimes-preset-1 = Non amorti ζ = 0
regimes-preset-2 = Sous-amorti ζ = 0,2
regimes-preset-3 = Amortissement critique ζ = 1
regimes-preset-4 = Suramorti ζ = 2
regimes-preset-5 = Amortissement négatif ζ = −0,1
regimes-table-caption = Les régimes d'amortissement
regimes-table-column-1 = régime
regimes-table-column-2 = condition
regimes-table-column-3 = racines s₁, s₂
regimes-table-column-4 = comportement
regimes-table-column-5 = exemples en ingénierie
regimes-table-undamped-1 = Non amorti
regimes-table-undamped-2 = ζ = 0
regimes-table-undamped-3 = ±iωₙ, sur l'axe imaginaire
regimes-table-undamped-4 = oscille indéfiniment à ωₙ
regimes-table-undamped-5 = pendule idéal, circuit oscillant LC
regimes-table-underdamped-1 = Sous-amorti
regimes-table-underdamped-2 = 0 < ζ < 1
regimes-table-underdamped-3 = −ζωₙ ± iω_d, paire complexe
regimes-table-underdamped-4 = oscillation décroissante à ω_d
regimes-table-underdamped-5 = suspension automobile (ζ ≈ 0,2–0,7), corde de guitare
regimes-table-critically-damped-1 = Amortissement critique
regimes-table-critically-damped-2 = ζ = 1
regimes-table-critically-damped-3 = −ωₙ, racine réelle double
regimes-table-critically-damped-4 = retour le plus rapide sans oscillation
regimes-table-critically-damped-5 = ferme-porte, aiguille de galvanomètre analogique
regimes-table-overdamped-1 = Suramorti
regimes-table-overdamped-2 = ζ > 1
regimes-table-overdamped-3 = deux racines réelles négatives
regimes-table-overdamped-4 = retour lent, sans oscillation
regimes-table-overdamped-5 = amortisseur hydraulique lourd, thermomètre
regimes-table-negatively-damped-1 = Amortissement négatif
regimes-table-negatively-damped-2 = ζ < 0
regimes-table-negatively-damped-3 = demi-plan droit
regimes-table-negatively-damped-4 = oscillation croissante
regimes-table-negatively-damped-5 = flottement (pont de Tacoma Narrows), freins qui crissent
### quarter-car

quarter-car-legend-comfort = confort { $low } et { $high }
quarter-car-legend-performance = sport { $low } et { $high }
quarter-car-legend-critical = critique { $zeta } (×)
quarter-car-legend-overdamped = suramorti { $zeta } (●)
quarter-car-group = { $group ->
        [comfort] confort
        [performance] sport
        [critical] critique
       *[overdamped] suramorti
    }
quarter-car-crossings = { $count ->
        [0] ne traverse pas l'équilibre
        [one] traverse l'équilibre une fois avant de se stabiliser
       *[other] traverse l'équilibre { $count } fois avant de se stabiliser
    }
quarter-car-crossings-inside-band = se stabilise avant de traverser l'équilibre (son rebond reste dans la bande)
quarter-car-settles-after = reste dans ±{ $band } de x₀ autour du repos après { $time }
quarter-car-does-not-settle = ne se stabilise pas
quarter-car-rebound = rebond maximal de { $rebound } à { $time }
quarter-car-no-rebound = aucun rebond
quarter-car-describe-design = Ce réglage (ζ = { $zeta }, { $regime }) : { $crossings }, { $settling }, { $rebound }.
quarter-car-describe-undamped = Ce réglage (ζ = 0, non amorti) : oscille indéfiniment entre ±{ $amplitude } à { $frequency }.
quarter-car-describe-unsettled = Ce réglage ({ $regime }) : ne se stabilise pas.
quarter-car-list-separator = {" ; "}
quarter-car-describe-response = { $design } Réglages de référence sur cette voiture, stabilisation dans ±{ $band } de x₀ : { $family }.
quarter-car-member-settles = { $group } ζ = { $zeta } en { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } ne se stabilise pas
quarter-car-two-sentences = { $first } { $second }
quarter-car-settling-fastest = Temps d'établissement de la réponse libre dans ±{ $band } de x₀ en fonction de ζ pour cette voiture : le plus court à ζ = { $zeta } ({ $time }), juste après un saut ; il chute brusquement chaque fois qu'un rebond passe à l'intérieur de la bande.
quarter-car-settling-curve = Temps d'établissement de la réponse libre dans ±{ $band } de x₀ en fonction de ζ.
quarter-car-settling-design = Ce réglage, ζ = { $zeta }, se stabilise en { $time }.
quarter-car-settling-design-never = Ce réglage, ζ = { $zeta }, ne se stabilise jamais.
quarter-car-sensitivity-range = Avec une masse suspendue entre { $low } et { $high } (±{ $variation }) et les mêmes amortisseur et ressort, ζ varie de { $min } à { $max } (nominal { $nominal }) ; l'estimation linéaire va de { $linear_min } à { $linear_max }.
quarter-car-sensitivity-undefined = La plage du taux d'amortissement n'est pas définie pour ce réglage.
quarter-car-sensitivity-inside = Le ζ de stabilisation la plus rapide, { $zeta }, se trouve dans cette plage : les charges qui font passer ζ en dessous se stabilisent nettement plus tard.
quarter-car-sensitivity-outside = Le ζ de stabilisation la plus rapide, { $zeta }, se trouve hors de cette plage.
quarter-car-schematic = Quart de véhicule à t = { $time } : la caisse est à { $displacement } du repos ({ $side ->
        [above] au-dessus
       *[below] en dessous
    }), route fixe.
quarter-car-settling-title = Temps d'établissement dans ±{ $band } de x₀ en fonction de ζ
quarter-car-axis-zeta = taux d'amortissement ζ
quarter-car-axis-zeta-fastest = taux d'amortissement ζ (tirets : ζ le plus rapide = { $zeta })
quarter-car-axis-settling-time = temps d'établissement t_s
quarter-car-axis-sprung-mass = masse suspendue m
quarter-car-fastest = ζ le plus rapide = { $zeta }
quarter-car-this-design = ce réglage
quarter-car-nominal = nominale
quarter-car-road = route
quarter-car-band-label = ±{ $band } de x₀
quarter-car-series-design = ce réglage, ζ { $zeta }
quarter-car-title = Suspension quart de véhicule
quarter-car-summary = Un coin de voiture : la caisse (masse suspendue m) sur un ressort k et un amortisseur c au-dessus d'une route fixe, déplacée de x₀ puis lâchée sans vitesse (x′(0) = 0). c et ζ sont deux vues du même amortisseur, c = 2ζ√(km) : déplacez l'un, l'autre suit ; changer m ou k conserve l'amortisseur, donc ζ varie. Les courbes fines montrent les réglages classiques sur cette voiture : le réglage confort (ζ ≈ 0,3–0,4) rebondit, le réglage sport (ζ ≈ 0,65–0,7) se stabilise le plus vite, les réglages critique (ζ = 1) et suramorti reviennent sans rebond, mais plus lentement. Le temps d'établissement saute quand ζ franchit les valeurs où un rebond passe à l'intérieur de la bande : le ζ le plus rapide se trouve juste après un tel saut, si bien qu'une charge plus lourde peut faire basculer une voiture bien réglée (voir le graphique de la masse). La stabilisation est mesurée sur cette réponse libre : le temps d'établissement est le dernier instant où |x| vaut bande·|x₀|, après quoi la caisse reste dans ±bande·|x₀| autour du repos (et non dans la bande autour de la valeur finale d'une réponse indicielle).
quarter-car-param-m = masse suspendue
quarter-car-param-k = raideur du ressort
quarter-car-param-c = coefficient d'amortissement
quarter-car-param-zeta = taux d'amortissement
quarter-car-param-x0 = déplacement initial
quarter-car-param-band = bande de stabilisation autour du repos, relative à x₀
quarter-car-param-dm = variation de la masse suspendue
quarter-car-readout-regime = régime
quarter-car-readout-wn = pulsation propre ωₙ
quarter-car-readout-fn = fréquence propre fₙ
quarter-car-readout-zeta = taux d'amortissement ζ
quarter-car-readout-c = coefficient d'amortissement c utilisé
quarter-car-readout-c-crit = amortissement critique 2√(km)
quarter-car-readout-wd = pulsation amortie ω_d
quarter-car-readout-settling-time = temps d'établissement t_s dans ±bande·|x₀| (réponse libre)
quarter-car-readout-overshoot = rebond maximal (rapporté à x₀)
quarter-car-readout-peak-time = instant du rebond maximal
quarter-car-readout-zeta-argmin = ζ de stabilisation la plus rapide (réponse libre, même bande)
quarter-car-readout-settling-min = son temps d'établissement
quarter-car-readout-zeta-lo = ζ à masse +dm %
quarter-car-readout-zeta-hi = ζ à masse −dm %
quarter-car-plot-response = Déplacement de la caisse x(t)
quarter-car-plot-settling = Temps d'établissement de la réponse libre en fonction de ζ
quarter-car-plot-sensitivity = ζ quand la masse suspendue varie
quarter-car-preset-1 = Confort ζ = 0,3
quarter-car-preset-2 = Confort ζ = 0,4
quarter-car-preset-3 = Sport ζ = 0,65
quarter-car-preset-4 = Sport ζ = 0,7
quarter-car-preset-5 = Critique ζ = 1
quarter-car-preset-6 = Suramorti ζ = 2

### quarter-car-2dof

quarter-car-2dof-describe-motion = Sur { $road ->
        [bump] une bosse
        [step] une marche
        [sine] une route sinusoïdale
       *[random] une route aléatoire
    } (hauteur maximale de la route { $road_peak }), la caisse se déplace d'au plus { $body } (à { $body_time }) et la roue d'au plus { $wheel } (à { $wheel_time }).
quarter-car-2dof-describe-acceleration = L'accélération de la caisse culmine à { $peak } ({ $peak_g } g) ; sur le trajet depuis le repos, de 0 à { $window }, sa valeur efficace est de { $rms }.
quarter-car-2dof-describe-tyre-lift-off = La déflexion du pneu (roue au-dessus de la route, positive = pneu qui se décharge) varie de { $low } à { $high }, valeur efficace { $rms } ; elle atteint la déflexion statique { $limit } pour la première fois à { $time }, où la force du pneu tombe à zéro et la roue quitte la route : décollements { $lift_offs } ; temps hors de la route { $airborne }.
quarter-car-2dof-describe-tyre-contact = La déflexion du pneu (roue au-dessus de la route, positive = pneu qui se décharge) varie de { $low } à { $high }, valeur efficace { $rms } ; elle reste sous la déflexion statique { $limit }, donc le pneu garde le contact.
quarter-car-2dof-describe-frf = Réponse en fréquence par unité de hauteur de route, en axes logarithmiques. La caisse suit les ondulations lentes de la route (rapport 1), culmine à { $body_peak } près du pompage de la caisse à { $body_frequency }, et est isolée au-delà : { $at_20 } à 20 Hz. La déflexion du pneu culmine à { $tyre_peak } près du battement de roue à { $tyre_frequency }.
quarter-car-2dof-schematic = Quart de véhicule à t = { $time } : caisse { $body }, roue { $wheel }, route { $road } (dessinées à une échelle commune).
quarter-car-2dof-schematic-title = Schéma
quarter-car-2dof-axis-height = hauteur par rapport à l'équilibre
quarter-car-2dof-axis-acceleration = accélération z_s″
quarter-car-2dof-axis-tyre-deflection = déflexion du pneu z_u − u
quarter-car-2dof-axis-frequency = fréquence f
quarter-car-2dof-axis-magnitude = amplitude par unité de hauteur de route
quarter-car-2dof-series-road = route u
quarter-car-2dof-series-wheel = roue z_u
quarter-car-2dof-series-body = caisse z_s
quarter-car-2dof-series-body-acceleration = accélération de la caisse
quarter-car-2dof-series-rms = ± valeur efficace
quarter-car-2dof-series-lift-off = décollement (déflexion statique)
quarter-car-2dof-series-off-road = roue décollée
quarter-car-2dof-series-body-gain = caisse/route
quarter-car-2dof-series-tyre-gain = défl. pneu/route
quarter-car-2dof-marker-road = route
quarter-car-2dof-title = Quart de véhicule avec caisse et roue
quarter-car-2dof-summary = Deux masses, deux modes. La caisse (masse suspendue m_s) repose sur le ressort de suspension k_s et l'amortisseur c_s ; la roue (masse non suspendue m_u) repose sur le ressort du pneu k_t, qui suit la route u(t). Le pompage de la caisse, vers 1–1,5 Hz, est le mouvement de la caisse sur la suspension souple ; le battement de roue, vers 10–15 Hz, est la roue légère qui rebondit entre le pneu raide et la suspension. Les réponses en fréquence montrent les deux : la caisse suit les ondulations lentes de la route, passe par-dessus les rapides et vibre le plus près du pompage ; la déflexion du pneu, qui décide de l'adhérence, culmine au battement de roue. Le pneu ne peut que pousser : quand la roue remonte au-delà de sa déflexion statique, la force du pneu est nulle et la roue quitte la route jusqu'à ce qu'elle retombe. Le confort se juge à l'accélération efficace (RMS) de la caisse, la tenue de route à la déflexion efficace du pneu, toutes deux sur le trajet depuis le repos, 0 … T. La réponse est exacte entre les échantillons de la route, assez rapprochés pour suivre chaque bosse et chaque battement de roue. Les déplacements sont comptés depuis l'équilibre statique, positifs vers le haut ; la route aléatoire additionne 64 sinusoïdes selon le spectre ISO 8608 sur 0,5–20 Hz. Sur celle-ci, la page indique aussi l'accélération efficace stationnaire de la caisse sur la route ISO 8608 complète, non pondérée et pondérée par le filtre W_k de l'ISO 2631-1 (a_w, la mesure du confort), tirée de l'équation de Lyapunov de la voiture.
quarter-car-2dof-param-ms = masse de la caisse (suspendue)
quarter-car-2dof-param-mu = masse de la roue (non suspendue)
quarter-car-2dof-param-ks = raideur de la suspension
quarter-car-2dof-param-kt = raideur du pneu
quarter-car-2dof-param-cs = amortissement de la suspension
quarter-car-2dof-param-road = excitation de la route
quarter-car-2dof-param-road-bump = bosse unique (1 − cos)
quarter-car-2dof-param-road-step = marche (bordure de trottoir)
quarter-car-2dof-param-road-sine = sinusoïde
quarter-car-2dof-param-road-random = route aléatoire (ISO 8608)
quarter-car-2dof-param-h = hauteur de la bosse ou de la marche, amplitude du sinus
quarter-car-2dof-param-L = longueur de la bosse
quarter-car-2dof-param-V = vitesse
quarter-car-2dof-param-f-road = fréquence de la route sinusoïdale
quarter-car-2dof-param-class = classe de la route aléatoire
quarter-car-2dof-param-class-A = A (très bonne)
quarter-car-2dof-param-class-B = B (bonne)
quarter-car-2dof-param-class-C = C (moyenne)
quarter-car-2dof-param-class-D = D (mauvaise)
quarter-car-2dof-param-class-E = E (très mauvaise)
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = graine de la route aléatoire
quarter-car-2dof-readout-f-body = fréquence de pompage de la caisse
quarter-car-2dof-readout-f-wheel = fréquence de battement de roue
quarter-car-2dof-readout-window = fenêtre de la valeur efficace : le trajet depuis le repos, 0 … T
quarter-car-2dof-readout-rms-body-accel = accélération efficace de la caisse sur 0 … T (confort)
quarter-car-2dof-readout-rms-tyre-deflection = déflexion efficace du pneu z_u − u sur 0 … T (tenue de route)
quarter-car-2dof-readout-max-travel = plus grand débattement de suspension |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = déflexion statique du pneu (la roue décolle au-delà)
quarter-car-2dof-readout-lift-off = premier décollement : la force du pneu atteint zéro
quarter-car-2dof-readout-airborne-time = durée pendant laquelle la roue a quitté la route
quarter-car-2dof-readout-rms-road = hauteur efficace de la route (route aléatoire)
quarter-car-2dof-readout-stationary-accel = accélération efficace stationnaire de la caisse, route ISO 8608 complète (route aléatoire)
quarter-car-2dof-readout-stationary-weighted-accel = a_w stationnaire : accélération efficace de la caisse pondérée par W_k de l'ISO 2631-1 (route aléatoire)
quarter-car-2dof-readout-body-gain = amplitude caisse / route à la fréquence du sinus
quarter-car-2dof-readout-tyre-gain = déflexion du pneu / amplitude de la route à la fréquence du sinus
quarter-car-2dof-plot-motion = Caisse, roue et route
quarter-car-2dof-plot-accel = Accélération de la caisse
quarter-car-2dof-plot-frf = Réponse en fréquence par unité de hauteur de route
quarter-car-2dof-plot-tyre = Déflexion du pneu
quarter-car-2dof-preset-1 = Ralentisseur de 5 cm à 10 m/s
quarter-car-2dof-preset-2 = Bordure de trottoir de 5 cm
quarter-car-2dof-preset-3 = Ondulation au pompage de la caisse
quarter-car-2dof-preset-4 = Ondulation au battement de roue
quarter-car-2dof-preset-5 = Route aléatoire, classe C, 20 m/s
quarter-car-2dof-preset-6 = Amortisseur souple sur route dégradée


### paper

paper-unavailable = la démo de cette figure n'est pas disponible
paper-pending-plot = tracé une fois l'application complète chargée
paper-pending-mark = chargement…
paper-pending-value = …
paper-pending = Vérifié dès que l'application complète est chargée, dans un instant.
paper-figure = Figure { $number }
paper-section = Section { $number }
paper-section-figure = Section { $section }, figure { $figure }
paper-near-agrees = La démo calcule { $computed }, conforme à l'arrondi près à la valeur de l'article, { $claimed } (tolérance ±{ $tolerance }).
paper-near-differs = La démo calcule { $computed }, et non la valeur de l'article, { $claimed } (tolérance ±{ $tolerance }).
paper-below-agrees = La démo calcule { $computed }, soit moins que la borne de { $bound } donnée par l'article.
paper-below-differs = La démo calcule { $computed }, soit plus que la borne de { $bound } donnée par l'article.
paper-range = { $low } à { $high }
paper-range-agrees = La démo calcule de { $low } à { $high }, comme le dit l'article.
paper-range-differs = La démo calcule de { $low } à { $high }, et non l'intervalle de l'article.
paper-peak = Le maximum de |H(r)| trouvé par recherche se situe en r = { $found }, là où la formule donne { $formula }.
paper-slope = Sur le pas de l'article, h = { $step }, et cinq divisions par deux (jusqu'à { $smallest }), la pente ajustée vaut { $slope }.
paper-reason-context = { $verdict } { $context }
paper-exhibit-fig1a = Réponse libre du quart de véhicule (m = 300 kg, k = 24 kN/m, x₀ = 60 mm) pour les réglages confort, performance, critique et suramorti.
paper-exhibit-fig1b = Temps d'établissement en fonction du taux d'amortissement, avec son minimum.
paper-exhibit-fig2a = Courant dans le circuit RLC série (L = 0,5 H, C = 20 mF, V₀ = 12 V) lorsque la résistance parcourt les régimes.
paper-exhibit-fig2b = Tension aux bornes du condensateur du même circuit.
paper-exhibit-fig3a = Module de la réponse en fréquence pour une famille de taux d'amortissement.
paper-exhibit-fig3b = Phase de la réponse en fréquence.
paper-exhibit-fig4a = Euler et RK4 comparés à la réponse exacte d'un oscillateur faiblement amorti (ζ = 0,05, ωₙ = 2 rad/s) avec h = 0,3 s.
paper-exhibit-fig4b = Erreur maximale en fonction du pas en axes log–log, avec les pentes.
paper-exhibit-fig5 = Une équation, de nombreuses machines : systèmes mécaniques, électriques et autres régis par la même équation a·y'' + b·y' + c·y = f(t).
paper-exhibit-table1 = L'analogie mécanique–électrique : masse ↔ inductance, amortisseur ↔ résistance, ressort ↔ 1/capacité.
paper-exhibit-table2 = Les régimes d'amortissement : condition, racines, comportement et exemples.
paper-exhibit-table3 = Les méthodes d'intégration comparées : erreur, ordre et stabilité pour un même pas.
paper-claim-fig1-zeta-optimum = Un taux d'amortissement d'environ 0,7 donne le temps d'établissement le plus court (bande de 5 %).
paper-claim-sec3-natural-frequency = La pulsation propre du quart de véhicule est d'environ 8,9 rad/s (environ 1,4 Hz).
paper-claim-sec4-critical-resistance = Le circuit est en amortissement critique pour R = 2√(L/C) = 10 Ω.
paper-claim-fig3-q-factor = Q = 10 pour ζ = 0,05.
paper-claim-fig3-q-factor-light = Q = 50 pour ζ = 0,01.
paper-claim-sec5-peak-frequency = La réponse culmine à ω = ωₙ√(1 − 2ζ²), juste en dessous de ωₙ (vérifié pour ζ = 0,1).
paper-claim-fig4-euler-error = Avec h = 0,3 s, l'erreur maximale d'Euler est d'environ 0,08.
paper-claim-fig4-rk4-error = Avec h = 0,3 s, l'erreur maximale de RK4 est inférieure à 0,001.
paper-claim-fig4-euler-slope = L'erreur d'Euler décroît avec une pente ≈ 1 sur le graphe log–log.
paper-claim-sec7-mass-tolerance = Une incertitude de ±10 % sur la masse suspendue fait passer ζ = 1,0 à une valeur comprise entre 0,91 et 1,10.
paper-claim-fig1-zeta-optimum-context = Pour une bande de 2 %, le ζ qui s'établit le plus vite est plutôt { $value }.
paper-claim-sec3-natural-frequency-context = En hertz : fₙ = { $value }.
paper-claim-fig4-euler-error-context = Euler est instable avec ce pas : |1 + hλ| = { $value } par pas, donc son erreur croît sans limite.
paper-claim-fig4-rk4-error-context = RK4 est stable avec ce pas (|R(hλ)| = { $value } par pas), mais sur toute la fenêtre son erreur dépasse la borne.
paper-claim-fig4-euler-slope-context = L'ordre ajusté sur les petits pas, où l'erreur est asymptotique, vaut { $value }.
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) varie comme 1/√m : une masse à ±10 % ne le déplace donc que d'environ ±5 % (ωₙ descend à { $value } à +10 %).
paper-title = L'article, vérifié
paper-summary = Zeta Lab est né d'un article sur les équations différentielles du second ordre dans les systèmes mécaniques et électriques (Ihenacho, Samuel, Okechukwu et al., Science Publishing Group, 2026). Voici chacune de ses figures et chacun de ses tableaux, tracés en direct par la démo qui les reproduit, et chacun des nombres qu'il avance, vérifié : chaque affirmation montre la valeur de l'article, la valeur calculée par l'application et un verdict. Suivez un lien pour ouvrir la démo exactement dans cet état.
paper-readout-claims = affirmations vérifiées
paper-readout-confirmed = affirmations confirmées
paper-readout-differs = affirmations qui diffèrent
paper-plot-fig1a = Figure 1(a)
paper-plot-fig1b = Figure 1(b)
paper-plot-fig2a = Figure 2(a)
paper-plot-fig2b = Figure 2(b)
paper-plot-fig3a = Figure 3(a)
paper-plot-fig3b = Figure 3(b)
paper-plot-fig4a = Figure 4(a)
paper-plot-fig4b = Figure 4(b)
paper-plot-fig5 = Figure 5
paper-plot-table1 = Tableau 1
paper-plot-table2 = Tableau 2
paper-plot-table3 = Tableau 3

### resonance

resonance-axis-ratio = rapport de fréquences r = ω/ωₙ
resonance-axis-amplification = amplification |H| = X/(F₀/k)
resonance-axis-magnitude-db = module 20·log₁₀|H|
resonance-axis-phase = phase ∠H (retard de x sur F)
resonance-plot-magnitude-db = Amplification |H(r)| en dB
resonance-family = famille ζ = { $from } … { $to }
resonance-current = ζ actuel = { $zeta }
resonance-drive = excitation r = { $ratio }
resonance-peak = pic
resonance-quadrature = −90° en r = 1
resonance-legend-width = largeur à demi-puissance r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2 jusqu'à r = { $upper }
resonance-legend-cutoff = coupure à −3 dB r = { $upper }
resonance-band-width = points à demi-puissance (|H| = |H|max/√2) en r = { $lower } et { $upper } : largeur du pic r₂ − r₁ = { $width }
resonance-band-broad = |H| reste au-dessus de |H|max/√2 de r = 0 jusqu'à r = { $upper } : le pic n'a pas de point inférieur à demi-puissance, sa largeur à demi-puissance n'est donc pas définie
resonance-band-cutoff = |H| tombe à 1/√2 de sa valeur statique (−3 dB) à la coupure r = { $upper } ; sans pic, il n'y a pas de largeur à demi-puissance
resonance-peak-at = pic de résonance { $gain } en r = { $ratio }
resonance-no-peak = pas de pic de résonance (ζ ≥ 1/√2) : |H| ne fait que décroître depuis 1 en r = 0
resonance-describe-magnitude = { $view ->
        [db] Module en dB pour ζ = { $zeta } : { $peak } ; { $band }. À l'excitation r = { $drive }, l'amplification vaut { $gain }.
       *[linear] Module pour ζ = { $zeta } : { $peak } ; { $band }. À l'excitation r = { $drive }, l'amplification vaut { $gain }.
    }
resonance-describe-phase = Retard de phase du déplacement sur la force pour ζ = { $zeta } : 0° à basse fréquence, −90° en r = 1 quel que soit le taux d'amortissement, vers −180° au-dessus de la résonance ; plus ζ est petit, plus la bascule est brusque. À l'excitation r = { $drive }, le retard vaut { $degrees } ({ $radians } rad).
resonance-envelope = enveloppe ±E(t)
resonance-steady-amplitude = amplitude permanente ±X
resonance-describe-time-growing = Excitée depuis le repos à r = { $ratio } (ω = { $omega }) pendant { $span } : pas de régime permanent ; l'amplitude croît et atteint { $largest }.
resonance-describe-time = { $case ->
        [beats] Excitée depuis le repos à r = { $ratio } (ω = { $omega }) pendant { $span } : les mouvements libre et forcé battent avec une période { $period } (constante de temps de la décroissance { $tau }), vers l'amplitude permanente { $amplitude }, avec un retard de { $lag } sur la force. Plus grand écart affiché : { $largest }.
        [build-up] Excitée depuis le repos à r = { $ratio } (ω = { $omega }) pendant { $span } : à la résonance, l'amplitude croît vers l'amplitude permanente { $amplitude } avec la constante de temps 1/(ζωₙ) = { $tau }, avec un retard de { $lag } sur la force. Plus grand écart affiché : { $largest }.
       *[transient] Excitée depuis le repos à r = { $ratio } (ω = { $omega }) pendant { $span } : après un régime transitoire (constante de temps { $tau }), elle se stabilise à l'amplitude permanente { $amplitude }, avec un retard de { $lag } sur la force. Plus grand écart affiché : { $largest }.
    }
resonance-fixed-base = bâti fixe
resonance-schematic = Masse sur un ressort et un amortisseur au-dessus d'un bâti fixe, poussée par la force F(t) = { $force } (flèche au-dessus de la masse) à t = { $time } : écartée de { $displacement } par rapport au repos.
resonance-beats-visible = visibles
resonance-beats-no-free-oscillation = aucun (pas d'oscillation libre, ζ ≥ 1)
resonance-beats-no-drive = aucun (force constante)
resonance-beats-same-frequency = aucun (excitation à ω_d)
resonance-beats-too-fast = aucun (aussi rapides que l'oscillation)
resonance-beats-dies-out = aucun (le mouvement libre s'éteint avant)
resonance-title = Résonance forcée
resonance-summary = Une masse de 1 kg sur un ressort (k = ωₙ²·m) et un amortisseur (c = 2ζωₙ·m), au repos, est excitée à partir de t = 0 par F(t) = F₀·cos(ωt). En régime permanent, elle oscille à la fréquence d'excitation avec l'amplitude |H(r)|·F₀/k, en retard sur la force d'un angle égal à la phase de H, où r = ω/ωₙ. Un faible amortissement donne un pic haut et étroit près de r = 1 (hauteur ≈ Q = 1/(2ζ)). Sa largeur à demi-puissance, r₂ − r₁ entre les deux rapports de fréquences où |H| = |H|max/√2, vaut ≈ 2ζ pour un faible amortissement ; au-delà de ζ ≈ 0,383, le point inférieur atteint r = 0 et la largeur n'est pas définie, et au-delà de ζ = 1/√2, il n'y a plus de pic du tout. Excitée exactement à la résonance, l'amplitude croît en quelques constantes de temps 1/(ζωₙ) sans battements ; excitée près de la résonance, les mouvements libre et forcé battent l'un contre l'autre jusqu'à ce que la partie libre s'éteigne.
resonance-param-zeta = taux d'amortissement
resonance-param-r = rapport d'excitation ω/ωₙ
resonance-param-wn = pulsation propre
resonance-param-F0 = amplitude de la force
resonance-param-view = affichage du module
resonance-param-view-linear = |H| linéaire
resonance-param-view-db = décibels 20·log₁₀|H|
resonance-readout-peak-gain = pic de résonance |H|max
resonance-readout-peak-ratio = pic en r = ω/ωₙ
resonance-readout-Q = facteur de qualité Q = 1/(2ζ)
resonance-readout-peak-width = largeur à demi-puissance du pic de |H| r₂ − r₁ (ζ < 0,383)
resonance-readout-gain-at-r = gain |H(r)| à l'excitation
resonance-readout-phase-at-r = phase ∠H(r) à l'excitation
resonance-readout-amplitude = amplitude permanente X = |H|·F₀/k
resonance-readout-beat-period = période des battements 2π/|ω − ω_d| (quand ils sont visibles)
resonance-readout-beats = battements dans x(t)
resonance-plot-magnitude = Amplification |H(r)|
resonance-plot-phase = Phase ∠H(r)
resonance-plot-time = Réponse depuis le repos x(t)
resonance-preset-1 = À la résonance, ζ = 0,05
resonance-preset-2 = Battements près de la résonance, r = 0,9
resonance-preset-3 = Pas de pic, ζ ≈ 1/√2
resonance-preset-4 = Quasi statique, r = 0,2
resonance-preset-5 = Isolation, r = 3

### flutter

flutter-no-oscillation = pas d'oscillation
flutter-series-h-section = section en H de 1940 (approx. pédagogique)
flutter-series-box = caisson profilé (plaque plane, Theodorsen)
flutter-series-simplest = A₂* équivalent au modèle le plus simple
flutter-series-simplest-line = modèle le plus simple ζ_s − g·U
flutter-axis-reduced-velocity = vitesse réduite U/(f·B) = 2π/K
flutter-axis-wind-speed = vitesse du vent U
flutter-axis-effective-damping = taux d'amortissement effectif ζ_eff
flutter-axis-twist = rotation θ
flutter-threshold = seuil 4Iζ_s/(ρB⁴) = { $value }
flutter-upper-pole = pôle supérieur
flutter-lower-pole = pôle inférieur
flutter-amplitude = amplitude ±a(t)
flutter-limit-cycle = cycle limite ±{ $amplitude }
flutter-describe-derivative = A₂* en fonction de la vitesse réduite pour { $model ->
        [h] la section en H de 1940 (approximation pédagogique, pas des valeurs mesurées)
        [box] le caisson profilé, idéalisé en plaque plane mince (valeurs exactes de Theodorsen en écoulement potentiel)
       *[simplest] le modèle le plus simple (l'A₂* auquel équivaut sa droite en U)
    } : la rotation croît là où A₂* dépasse 4Iζ_s/(ρB⁴).
flutter-describe-derivative-now = { $description } À U = { $speed } (K = { $k }, U/(fB) = { $reduced_velocity }), A₂* = { $a2 }, { $side ->
        [above] au-dessus du
       *[below] en dessous du
    } seuil { $threshold }.
flutter-describe-damping = Taux d'amortissement effectif { $model ->
        [h] de la section en H de 1940
        [box] du caisson profilé
       *[simplest] du modèle le plus simple
    }, à partir de ζ_s = { $zeta_s } en air calme ; { $crossing ->
        [inside] il s'annule à la vitesse critique { $speed }
        [beyond] il ne s'annulerait qu'à { $speed }, au-delà du maximum tracé { $limit }
       *[never] il ne s'annule jamais jusqu'à 100 m/s : le vent ne fait qu'ajouter de l'amortissement
    }.
flutter-describe-damping-now = { $description } À U = { $speed }, il vaut { $zeta }, { $sign ->
        [positive] positif (stable)
        [negative] négatif (flottement)
       *[zero] nul
    }.
flutter-describe-damping-still = { $description } À cette vitesse de vent, le tablier n'oscille pas.
flutter-describe-locus = Paire de pôles quand le vent forcit : { $re_calm } ± { $im_calm }i 1/s en air calme, { $re_end } ± { $im_end }i 1/s à { $limit }, { $crosses ->
        [yes] en traversant l'axe imaginaire à U_crit
       *[no] sans jamais traverser l'axe imaginaire
    }.
flutter-describe-locus-now = { $description } À U = { $speed }, les pôles valent { $re } ± { $im }i 1/s, dans le demi-plan { $side ->
        [right] droit (instable)
       *[left] gauche (stable)
    }.
flutter-oscillation = l'oscillation
flutter-oscillation-at = l'oscillation à { $frequency } Hz
flutter-describe-response = { $regime } : à partir d'une rotation initiale de { $twist }, { $oscillation } { $case ->
        [settling] croît jusqu'à { $end } à la fin du tracé ({ $window }) et se stabilise près du cycle limite de { $limit } (90 % atteints après { $time })
        [slow] ne croît que jusqu'à { $end } à la fin du tracé ({ $window }) ; il faudrait { $time } pour atteindre 90 % du cycle limite de { $limit }
        [settled] se stabilise sur le cycle limite de { $limit } à la fin du tracé ({ $window })
        [grows] croît jusqu'à { $end } à la fin du tracé ({ $window })
       *[dies] décroît jusqu'à { $end } à la fin du tracé ({ $window })
    }.
flutter-describe-response-torn = { $description } Une rotation aussi grande aurait détruit n'importe quel tablier bien avant ; la borne n'est qu'une hypothèse pédagogique.
flutter-schematic-title = Section du tablier
flutter-drawn-clipped = dessin écrêté à { $angle }
flutter-drawn-true-scale = dessin à l'échelle réelle
flutter-drawn-larger = dessin agrandi { $factor } fois
flutter-drawn-note = ({ $drawn })
flutter-schematic = Section du tablier du pont à t = { $time } : rotation de { $twist } ({ $drawn }), vent de { $wind } venant de la gauche.
flutter-wind = vent U = { $speed }
flutter-title = Flottement : le pont de Tacoma Narrows
flutter-summary = Un vent constant peut fournir de l'énergie à un tablier de pont en torsion par l'intermédiaire de son propre mouvement. Scanlan a écrit le moment du vent sur un tablier en torsion à l'aide de dérivées de flottement mesurées en soufflerie : A₂* multiplie la vitesse de rotation (un terme d'amortissement) et A₃* la rotation (un terme de raideur), toutes deux fonctions de la fréquence réduite K = Bω/U. Le taux d'amortissement du tablier devient ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I) : pour la section en H non profilée du tablier de Tacoma de 1940, A₂* change de signe quand le vent forcit, et dès qu'il dépasse le seuil 4Iζ_s/(ρB⁴), toute petite rotation croît à la fréquence de torsion propre du tablier (près de 0,2 Hz) — c'est du flottement, pas de la résonance : un vent constant n'a aucune fréquence à laquelle s'accorder, le mouvement crée sa propre excitation. La fréquence est obtenue par itération à chaque vitesse de vent, puisque K en dépend. La théorie linéaire laisse la rotation croître indéfiniment ; ici, on suppose que le terme d'amortissement du vent est divisé par deux pour une rotation θ_s, ce qui borne le mouvement sur un grand cycle limite, comme le 7 novembre 1940, quand, par un vent d'environ 42 mph, la rotation a crû en moins d'une heure jusqu'à la rupture du tablier. Présenté comme tel : les A₂* et A₃* de la section en H sont une approximation pédagogique, des courbes lisses ayant l'allure des résultats publiés en soufflerie (Scanlan et Tomko 1971 ; Billah et Scanlan 1991), et non des valeurs relevées dans ces travaux ; I, ζ_s et θ_s sont supposés. Le caisson profilé est idéalisé en plaque plane mince, dont les A₂* et A₃* sont exacts en écoulement potentiel (Theodorsen 1935) : son A₂* reste négatif, il n'entre donc jamais en flottement dans cette plage. Le modèle le plus simple ζ_eff = ζ_s − g·U est conservé pour comparaison.
flutter-param-U = vitesse du vent
flutter-param-model = modèle du moment du vent
flutter-param-model-scanlan = dérivées de flottement (Scanlan)
flutter-param-model-linear = modèle le plus simple : ζ_eff = ζ_s − g·U
flutter-param-section = section du tablier
flutter-param-section-h = section en H de 1940 (poutres à âme pleine)
flutter-param-section-box = poutre-caisson profilée
flutter-param-B = largeur du tablier
flutter-param-I = moment d'inertie massique par unité de longueur (supposé pour 1940)
flutter-param-f0 = fréquence de torsion en air calme
flutter-param-zeta-s = taux d'amortissement structurel (supposé pour 1940)
flutter-param-theta0 = rotation initiale
flutter-param-theta-s = rotation pour laquelle l'amortissement du vent est divisé par deux (hypothèse pédagogique)
flutter-param-slope = modèle le plus simple : amortissement perdu par m/s
flutter-readout-regime = régime d'une petite rotation
flutter-readout-U-crit = vitesse critique (de flottement) U_crit, cherchée jusqu'à 100 m/s
flutter-readout-zeta-eff = taux d'amortissement effectif ζ_eff d'une petite rotation
flutter-readout-growth-rate = taux de croissance σ d'une petite rotation (< 0 : décroît)
flutter-readout-doubling-time = une petite rotation double toutes les
flutter-readout-frequency = fréquence de torsion dans le vent f
flutter-readout-K = fréquence réduite K = Bω/U
flutter-readout-reduced-velocity = vitesse réduite U/(f·B) = 2π/K
flutter-readout-A2 = dérivée de flottement A₂*(K)
flutter-readout-A3 = dérivée de flottement A₃*(K)
flutter-readout-limit-deg = amplitude de rotation du cycle limite (avec la borne supposée θ_s)
flutter-readout-time-to-large = temps pour passer de θ₀ à 90 % du cycle limite
flutter-readout-amplitude-end-deg = amplitude de rotation à la fin du tracé
flutter-plot-derivative = Dérivée de flottement A₂* et seuil de flottement
flutter-plot-damping = Amortissement effectif en fonction de la vitesse du vent
flutter-plot-locus = Lieu des racines quand le vent forcit
flutter-plot-response = Rotation du tablier θ(t) sur plusieurs minutes
flutter-preset-1 = Tacoma 1940, 10 m/s (stable)
flutter-preset-2 = Tacoma 1940, 19 m/s (jour de la rupture, ≈ 42 mph)
flutter-preset-3 = Tacoma 1940, coup de vent à 30 m/s
flutter-preset-4 = Tablier en caisson profilé, 19 m/s
flutter-preset-5 = Tablier en caisson profilé, 40 m/s
flutter-preset-6 = Modèle le plus simple, 19 m/s (ζ_eff = ζ_s − g·U)
flutter-table-caption = Le flottement n'est pas une résonance
flutter-table-column-1 = cas
flutter-table-column-2 = ce qui l'entretient
flutter-table-column-3 = fréquence
flutter-table-column-4 = amortissement
flutter-table-column-5 = amplitude
flutter-table-column-6 = remède
flutter-table-resonance-1 = Résonance forcée (pour comparaison)
flutter-table-resonance-2 = une force extérieure oscillant près de ωₙ (pas cadencés, un moteur)
flutter-table-resonance-3 = imposée par la force ; doit coïncider avec ωₙ
flutter-table-resonance-4 = positif : limite le pic à environ 1/(2ζ) × la réponse statique
flutter-table-resonance-5 = régime permanent borné
flutter-table-resonance-6 = désaccorder ou ajouter de l'amortissement
flutter-table-underdamped-1 = Vent inférieur à U_crit
flutter-table-underdamped-2 = vent constant ; moment ∝ vitesse de rotation (A₂*) et rotation (A₃*)
flutter-table-underdamped-3 = celle du tablier, légèrement décalée par A₃*
flutter-table-underdamped-4 = ζ_eff > 0 : A₂* sous le seuil 4Iζ_s/(ρB⁴)
flutter-table-underdamped-5 = une rotation s'amortit
flutter-table-underdamped-6 = —
flutter-table-undamped-1 = À U_crit
flutter-table-undamped-2 = vent constant ; moment ∝ vitesse de rotation (A₂*) et rotation (A₃*)
flutter-table-undamped-3 = celle du tablier
flutter-table-undamped-4 = ζ_eff = 0 : pôles sur l'axe imaginaire
flutter-table-undamped-5 = une rotation persiste sans changer
flutter-table-undamped-6 = —
flutter-table-negatively-damped-1 = Flottement, vent supérieur à U_crit
flutter-table-negatively-damped-2 = vent constant ; le mouvement crée sa propre excitation
flutter-table-negatively-damped-3 = celle du tablier, aucun accord nécessaire
flutter-table-negatively-damped-4 = ζ_eff < 0 : de l'énergie entre à chaque cycle
flutter-table-negatively-damped-5 = croît jusqu'à ce que la borne d'amplitude (ou le tablier) cède
flutter-table-negatively-damped-6 = une section dont l'A₂* reste négatif : tablier profilé, ajouré ou rigidifié
### integrators

integrators-join = { " ; " }
integrators-legend-dp45-order = DP45 : { $order }
integrators-overflow-note = dépassement de capacité à t = { $time }
integrators-failed = échec
integrators-stable-yes = oui
integrators-stable-no = non
integrators-method-euler = Euler explicite
integrators-method-symplectic-euler = Euler symplectique
integrators-method-heun = Heun
integrators-method-rk4 = RK4
integrators-legend-symplectic-euler = Euler sympl. ×
integrators-legend-euler = Euler
integrators-legend-heun = Heun
integrators-legend-dp45 = DP45 ● pas
integrators-legend-growing = { $legend } ×{ $growth }/pas ↑
integrators-legend-order = { $legend } : { $order }
integrators-legend-no-fit = { $legend } : pas d'ajustement
integrators-legend-dp45-no-order = DP45 : pas d'ordre
integrators-series-exact = exacte
integrators-axis-error = erreur |x_num − x_exact|
integrators-axis-step = pas h
integrators-axis-max-error = erreur maximale
integrators-axis-re = partie réelle Re(hλ)
integrators-axis-im = partie imaginaire Im(hλ)
integrators-axis-evaluations = évaluations du second membre N
integrators-limit-up-to = stable pour h ≤ { $step }
integrators-limit-every = stable pour tout h
integrators-limit-none = instable pour tout h
integrators-method-overflows = { $method } : dépassement de capacité à t = { $time } (×{ $growth } par pas)
integrators-method-diverges = { $method } diverge (×{ $growth } par pas), erreur maximale { $error }
integrators-method-diverges-clipped = { $method } diverge (×{ $growth } par pas, écrêté), erreur maximale { $error }
integrators-method-bounded = { $method } reste borné (×{ $growth } par pas), erreur maximale { $error }
integrators-dp45-words = DP45 a fait { $steps ->
        [one] { $steps } pas
       *[other] { $steps } pas
    } (tolérance { $tolerance }), erreur maximale { $error }
integrators-dp45-failed = échec de DP45 : { $reason }
integrators-failed-underflow = le pas est devenu trop petit pour avancer à t = { $time } (le problème est peut-être trop raide ou singulier)
integrators-failed-max-steps = abandon à t = { $time } après { $steps } pas
integrators-failed-non-finite = la solution est devenue infinie ou indéfinie à t = { $time } (essayez un pas plus petit)
integrators-describe-response = Chaque méthode face à l'oscillation amortie exacte sur { $duration } avec h = { $step } ({ $steps } pas). { $methods }. Le graphique montre ±{ $range } fois l'amplitude exacte ; les courbes qui la dépassent sont écrêtées au bord.
integrators-describe-response-last = Chaque méthode face à l'oscillation amortie exacte sur { $duration } avec h = { $step } ({ $steps } pas, le dernier de { $last } pour finir à T). { $methods }. Le graphique montre ±{ $range } fois l'amplitude exacte ; les courbes qui la dépassent sont écrêtées au bord.
integrators-error-peak = { $method } : maximum { $error } à t = { $time }
integrators-error-peak-growing = { $method } : maximum { $error } à t = { $time }, croissante
integrators-error-none = { $method } : aucune erreur finie
integrators-error-no-method = Aucune méthode n'est activée.
integrators-describe-error = Erreur |x_num − x_exact| en échelle logarithmique aux points de grille de chaque méthode (h = { $step }) : { $methods }.
integrators-describe-error-clipped = Erreur |x_num − x_exact| en échelle logarithmique aux points de grille de chaque méthode (h = { $step }) : { $methods }. Les erreurs supérieures à { $clip } sont écrêtées en haut.
integrators-fit = { $method } : pente ajustée { $slope } (h = { $from } … { $to })
integrators-fit-overflows = { $method } : pente ajustée { $slope } (h = { $from } … { $to }), dépassement de capacité pour h ≥ { $limit }
integrators-no-fit = { $method } : pas d'ajustement (trop peu de points dans le domaine asymptotique)
integrators-no-fit-overflows = { $method } : pas d'ajustement (trop peu de points dans le domaine asymptotique), dépassement de capacité pour h ≥ { $limit }
integrators-slope = pente { $order }
integrators-describe-convergence = Erreur maximale en { $points } points de contrôle communs en fonction du pas h, pour au plus { $levels } pas divisés par deux à partir de { $from } (au plus { $budget } pas par méthode au total, { $euler_budget } pour Euler explicite ; les pas plus fins sont omis). { $methods }. Chaque ordre est ajusté sur le seul domaine asymptotique, tracé en segment épais : les pas les plus fins dont les pentes locales concordent à { $spread } près, avec des erreurs inférieures à { $ceiling } et supérieures à 1e-10 de x₀. Les pentes de référence 1 et 4 sont en pointillés ; le h actuel est la verticale en tirets. DP45 n'a pas de h unique : voir le graphique travail–précision.
integrators-off-scale = { $name } = { $value } (hors échelle)
integrators-path = hλ quand h augmente
integrators-z-real-pair = z = hλ = { $z1 } et { $z2 }
integrators-region-inside = { $method } : dans sa région, |R| = { $growth }, { $limit }
integrators-region-outside = { $method } : hors de sa région, |R| = { $growth }, { $limit }
integrators-describe-stability = Régions de stabilité |R(z)| ≤ 1 dans le plan complexe de z = hλ (l'intérieur de chaque courbe fermée ; celle d'Euler explicite est le disque |1 + z| ≤ 1). Les deux pôles du système avec h = { $step } donnent { $z }. { $methods }. Euler symplectique n'est pas une application scalaire R(z) : sa matrice de pas 2×2 a ici un rayon spectral de { $radius }, { $limit }. DP45 choisit lui-même ses pas et les garde stables.
integrators-work-words = { $method } : de { $error_first } avec { $work_first } évaluations à { $error_last } avec { $work_last }
integrators-describe-work = Erreur maximale en fonction du travail qu'elle a coûté, compté en évaluations du second membre f, en axes log–log, pour chaque méthode : celles à pas fixe aux pas de l'étude de convergence (erreur en ses points de contrôle communs), DP45 aux tolérances { $from } … { $to } (erreur sur ses pas acceptés). Plus bas est plus précis, plus à gauche est moins coûteux ; une méthode d'ordre p descend avec une pente −p ; les calculs de DP45 sont des points là où la tolérance fixe leurs pas et des croix là où c'est la stabilité. { $methods }.
integrators-provisional = Provisoire : d'après une étude grossière (au plus { $budget } pas par méthode, { $euler_budget } pour Euler explicite ; DP45 jusqu'à { $tol }), pendant le calcul de l'étude complète ({ $full_budget } et { $full_euler_budget } pas ; DP45 jusqu'à { $full_tol }). { $description }
integrators-runs-provisional = Provisoire : les intégrations jusqu'ici, jusqu'à t = { $until } sur { $duration }, pendant le calcul de la suite. { $description }
integrators-dp45-stability-runs = calculs dont la stabilité fixe les pas (plus de { $share } des pas à { $fraction } ou plus de son plus grand pas stable) : { $count }/{ $runs }
integrators-dp45-order = DP45 : ordre observé { $order } (ajusté sur { $from } … { $to } évaluations, là où la tolérance fixe ses pas) ; { $runs }
integrators-dp45-no-order = DP45 n'a pas d'ordre observé : la stabilité fixe ses pas, ou il reste trop peu de calculs dans le domaine asymptotique ; { $runs }
integrators-title = Intégrateurs numériques et leur erreur
integrators-summary = L'oscillateur libre intégré par Euler explicite, Euler symplectique, Heun (RK2) et RK4 classique à pas fixe h, et par Dormand–Prince 5(4) à pas adaptatif, chacun comparé à la solution exacte. Une méthode à un pas multiplie chaque mode par R(hλ) à chaque pas : quand |R| > 1, les nombres croissent quelle que soit la fidélité avec laquelle la méthode approche l'équation, ce qui explique pourquoi Euler explicite fait exploser un oscillateur faiblement amorti sauf si h < 2ζ/ωₙ. Quand elle est stable, diviser h par deux divise l'erreur par 2^p, où p est l'ordre de convergence de la méthode : le graphique de convergence mesure p. Désactiver une méthode masque ses courbes ; ses valeurs affichées restent calculées.
integrators-param-zeta = taux d'amortissement
integrators-param-wn = pulsation propre
integrators-param-h = pas
integrators-param-T = durée
integrators-param-x0 = déplacement initial
integrators-param-tol = tolérance de DP45 (relative ; absolue tol·x₀)
integrators-param-euler = Euler explicite
integrators-param-symplectic-euler = Euler symplectique
integrators-param-heun = Heun (RK2)
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4), adaptatif
integrators-readout-h-used = pas utilisé, sauf le dernier
integrators-readout-h-last = dernier pas, qui termine le calcul à T
integrators-readout-max-err-euler = erreur maximale, Euler explicite
integrators-readout-max-err-symplectic-euler = erreur maximale, Euler symplectique
integrators-readout-max-err-heun = erreur maximale, Heun
integrators-readout-max-err-rk4 = erreur maximale, RK4
integrators-readout-max-err-dp45 = erreur maximale, DP45
integrators-readout-order-euler = ordre ajusté, Euler explicite
integrators-readout-order-symplectic-euler = ordre ajusté, Euler symplectique
integrators-readout-order-heun = ordre ajusté, Heun
integrators-readout-order-rk4 = ordre ajusté, RK4
integrators-readout-order-dp45 = ordre observé, DP45 (erreur en fonction des évaluations de f, là où la tolérance fixe les pas)
integrators-readout-stable-euler = stable à ce h, Euler explicite
integrators-readout-stable-symplectic-euler = stable à ce h, Euler symplectique
integrators-readout-stable-heun = stable à ce h, Heun
integrators-readout-stable-rk4 = stable à ce h, RK4
integrators-readout-growth-euler = croissance par pas |R(hλ)|, Euler explicite
integrators-readout-growth-symplectic-euler = croissance par pas (rayon spectral), Euler symplectique
integrators-readout-growth-heun = croissance par pas |R(hλ)|, Heun
integrators-readout-growth-rk4 = croissance par pas |R(hλ)|, RK4
integrators-readout-steps-dp45 = pas acceptés par DP45
integrators-plot-response = Solutions numériques et x(t) exacte
integrators-plot-error = Erreur au cours du temps
integrators-plot-convergence = Convergence : erreur maximale en fonction du pas h
integrators-plot-work = Travail–précision : erreur maximale en fonction des évaluations de f
integrators-plot-stability = Régions de stabilité et z = hλ
integrators-preset-1 = Faiblement amorti, h = 0,3 s
integrators-preset-2 = Euler tout juste stable, h = 0,04 s
integrators-preset-3 = RK4 au-delà de sa limite, h = 1,6 s
integrators-preset-4 = Non amorti, h = 0,1 s
integrators-preset-5 = Raide et suramorti ζ = 2, ωₙ = 20
integrators-table-caption = Les méthodes
integrators-table-column-1 = méthode
integrators-table-column-2 = ordre p
integrators-table-column-3 = évaluations de f par pas
integrators-table-column-4 = facteur d'amplification R(z)
integrators-table-column-5 = sur un oscillateur non amorti
integrators-table-euler-1 = Euler explicite
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = croît toujours : |R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = Euler symplectique
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = matrice 2×2, pas un R scalaire
integrators-table-symplectic-euler-5 = erreur d'énergie bornée tant que ωh ≤ 2
integrators-table-heun-1 = Heun (RK2)
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = croît lentement : |R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = RK4 classique
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = amortit légèrement tant que ωh ≤ 2√2
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6 (la dernière sert de première)
integrators-table-dp45-4 = adaptatif : h suit l'estimation d'erreur
integrators-table-dp45-5 = stable : les pas rejetés réduisent h

### nonlinear

nonlinear-effect-linear = linéaire
nonlinear-effect-hardening = ressort raidissant
nonlinear-effect-softening = ressort assouplissant
nonlinear-effect-stick-slip = adhérence-glissement
nonlinear-effect-bump-stop = choc sur la butée
nonlinear-effect-asymmetric = amortisseur asymétrique
nonlinear-effect-several = plusieurs à la fois
nonlinear-effect-escaped = échappement
nonlinear-join = { "\u00A0; " }
nonlinear-differ = elles diffèrent au plus de { $deviation } à t = { $time }
nonlinear-first-swing = première oscillation { $nonlinear } contre { $linear } en linéaire (rapport { $ratio })
nonlinear-sticks-at = le frottement retient la masse à { $position } à partir de { $time }
nonlinear-escapes = le calcul non linéaire sort du graphique (|x| > { $limit }) à { $time }
nonlinear-describe-response = { $effect } : les deux partent ensemble ; { $clauses }.
nonlinear-describe-phase = Plan de phase : les deux trajectoires partent de x = { $x0 }, v = { $v0 }. La linéaire s'enroule en spirale vers ({ $x_linear }, { $v_linear }) ; la non linéaire finit en x = { $x_end }, v = { $v_end }, avec une vitesse maximale de { $speed } contre { $speed_linear } en linéaire.
nonlinear-describe-spring = Force de rappel en fonction de l'extension sur ±{ $reach } : le ressort linéaire est la droite k·x ; au plus grand débattement, { $travel }, la force non linéaire vaut { $force } contre { $linear } en linéaire{ $stops ->
        [yes] , les butées ajoutant { $rate } au-delà de ±{ $gap }.
       *[no] .
    }
nonlinear-describe-damper = Force d'amortisseur et de frottement en fonction de la vitesse sur ±{ $speed } : à +{ $speed } (détente) elle vaut { $rebound }, à −{ $speed } (compression) { $compression } ; l'amortisseur moyen du modèle linéaire donne ±{ $linear }{ $coulomb ->
        [yes]  ; le frottement de glissement ajoute un saut de ±{ $friction } en v = 0, et au repos le frottement statique retient jusqu'à ±{ $holding }.
       *[no] .
    }
nonlinear-axis-velocity-rebound = vitesse v (+ détente)
nonlinear-series-stops = butées ±{ $gap }
nonlinear-series-linear = modèle linéaire
nonlinear-series-nonlinear = non linéaire (RK4)
nonlinear-marker-sticks = adhère
nonlinear-marker-start = départ
nonlinear-series-linear-spring = k·x linéaire
nonlinear-series-spring = k·x + k₃·x³ + butées
nonlinear-series-linear-damper = c̄·v linéaire
nonlinear-series-damper = amortisseur + frottement
nonlinear-schematic = Quart de véhicule à t = { $time } : suspension détendue de { $extension }{ $stops ->
        [pressing] , en appui sur une butée.
        [clear] , hors contact avec les butées.
       *[none] .
    }
nonlinear-title = Au-delà du modèle linéaire
nonlinear-summary = Une suspension réelle n'est linéaire que pour de petits mouvements. Ici, le quart de véhicule reçoit un ressort cubique (k₃ > 0 raidissant, k₃ < 0 assouplissant), un amortisseur plus ferme en détente (x′ > 0) qu'en compression, un frottement de Coulomb dans les articulations et des butées en caoutchouc au-delà de ±gap. Le frottement alterne adhérence et glissement : tant que la masse glisse, il freine avec la force F_c ; une fois qu'elle s'arrête, le frottement statique la retient jusqu'à F_static, un multiple fixé de F_c, et elle ne repart que si le ressort tire plus fort. Le mouvement est intégré par RK4, chaque arrêt localisé à l'intérieur de son pas, et tracé face au modèle linéaire m·x″ + c̄·x′ + k·x = 0 (c̄ le coefficient moyen de l'amortisseur) depuis le même départ. Observez où la prédiction échoue : la période dépend de l'amplitude (un ressort raidissant la raccourcit, un ressort assouplissant l'allonge), le frottement fait décroître l'amplitude en ligne droite puis retient définitivement la masse hors du centre (adhérence-glissement), une butée transforme une oscillation douce en choc, et un amortisseur asymétrique décale la position moyenne. Les valeurs par défaut sont un coin de voiture plausible : 300 kg, 24 kN/m (1,4 Hz), un amortisseur de 1 500 N·s/m (ζ ≈ 0,28) et un ressort légèrement progressif. x est l'extension de la suspension depuis l'équilibre statique (positive = caisse vers le haut).
nonlinear-param-m = masse suspendue
nonlinear-param-k = raideur linéaire du ressort
nonlinear-param-k3 = coefficient cubique du ressort (+ raidissant, − assouplissant)
nonlinear-param-c-comp = coefficient d'amortissement en compression
nonlinear-param-c-reb = coefficient d'amortissement en détente
nonlinear-param-friction = force de frottement de Coulomb en glissement
nonlinear-param-stick-ratio = rapport frottement statique / frottement de glissement
nonlinear-param-gap = jeu avant la butée
nonlinear-param-k-stop = raideur de butée (0 = sans butées)
nonlinear-param-x0 = extension initiale
nonlinear-param-v0 = vitesse initiale
nonlinear-readout-effect = non-linéarité dominante
nonlinear-readout-period-ratio = rapport des périodes de la première oscillation T_nonlinear / T_linear
nonlinear-readout-max-deviation = plus grand |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = période non linéaire de la première oscillation complète (trois passages par zéro)
nonlinear-readout-period-linear = période linéaire de la première oscillation complète (= 2π/ω_d)
nonlinear-readout-max-travel = plus grand |x| (non linéaire)
nonlinear-readout-stick-position = le frottement retient la masse à
nonlinear-plot-response = Réponse non linéaire et linéaire x(t)
nonlinear-plot-phase = Plan de phase (x, v)
nonlinear-plot-spring = Force du ressort et des butées
nonlinear-plot-damper = Force de l'amortisseur et du frottement
nonlinear-preset-1 = Linéaire (tout désactivé)
nonlinear-preset-2 = Ressort raidissant
nonlinear-preset-3 = Ressort assouplissant
nonlinear-preset-4 = Frottement adhérence–glissement
nonlinear-preset-5 = Choc sur la butée
nonlinear-preset-6 = Amortisseur asymétrique
nonlinear-table-caption = Où le modèle linéaire échoue
nonlinear-table-column-1 = non-linéarité
nonlinear-table-column-2 = loi de force
nonlinear-table-column-3 = ce que le modèle linéaire manque
nonlinear-table-column-4 = signature sur les graphiques
nonlinear-table-linear-1 = Aucune (linéaire)
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = rien : le modèle est exact
nonlinear-table-linear-4 = les deux courbes coïncident
nonlinear-table-hardening-spring-1 = Ressort raidissant
nonlinear-table-hardening-spring-2 = k·x + k₃·x³, k₃ > 0
nonlinear-table-hardening-spring-3 = la fréquence croît avec l'amplitude
nonlinear-table-hardening-spring-4 = période plus courte tant que l'oscillation est grande ; les courbes s'écartent
nonlinear-table-softening-spring-1 = Ressort assouplissant
nonlinear-table-softening-spring-2 = k·x + k₃·x³, k₃ < 0
nonlinear-table-softening-spring-3 = la fréquence décroît avec l'amplitude ; au-delà de √(−k/k₃) le ressort cède
nonlinear-table-softening-spring-4 = période plus longue ; un grand départ peut s'échapper
nonlinear-table-stick-slip-1 = Frottement de Coulomb
nonlinear-table-stick-slip-2 = F_c·sgn(x′) en glissement ; jusqu'à F_static au repos
nonlinear-table-stick-slip-3 = l'amplitude décroît d'environ 4F_c/k par cycle, en ligne droite, puis la masse reste collée définitivement là où |k·x| ≤ F_static
nonlinear-table-stick-slip-4 = enveloppe rectiligne ; une fin plate hors de zéro
nonlinear-table-bump-stop-impact-1 = Butées
nonlinear-table-bump-stop-impact-2 = k_stop·(|x| − gap) au-delà de ±gap
nonlinear-table-bump-stop-impact-3 = un contact brusque et raide : grande force, inversion rapide
nonlinear-table-bump-stop-impact-4 = pics écrêtés à ±gap ; cassures dans la boucle de phase
nonlinear-table-asymmetric-damper-1 = Amortisseur asymétrique
nonlinear-table-asymmetric-damper-2 = c_r·x′ en détente, c_c·x′ en compression
nonlinear-table-asymmetric-damper-3 = un décalage de la position moyenne (effet de « jacking ») et des demi-cycles inégaux
nonlinear-table-asymmetric-damper-4 = décroissance dissymétrique ; la spirale de phase est décentrée
nonlinear-table-several-at-once-1 = Plusieurs à la fois
nonlinear-table-several-at-once-2 = somme des précédentes
nonlinear-table-several-at-once-3 = leurs effets s'ajoutent et interagissent
nonlinear-table-several-at-once-4 = voir chaque ligne
nonlinear-table-escaped-1 = Ressort assouplissant au-delà de sa limite
nonlinear-table-escaped-2 = k·x + k₃·x³ < 0 pour |x| > √(−k/k₃)
nonlinear-table-escaped-3 = le modèle cesse de décrire une suspension
nonlinear-table-escaped-4 = le calcul est interrompu là où |x| dépasse 1 m

### uncertainty

uncertainty-quantity-zeta = taux d'amortissement ζ
uncertainty-quantity-f0 = fréquence propre f0
uncertainty-quantity-q = facteur de qualité Q
uncertainty-quantity-bandwidth = bande passante à demi-puissance
uncertainty-quantity-settling-time = temps d'établissement de la réponse libre (±5 %)
uncertainty-hist-title = Monte-Carlo : { $quantity }
uncertainty-draws-provisional = { $draws } ({ $full } en cours)
uncertainty-band-nominal-mass = m nominale
uncertainty-band-lowest-corner = coin de ζ minimal
uncertainty-band-nominal = nominal
uncertainty-band-highest-corner = coin de ζ maximal
uncertainty-never = jamais
uncertainty-band-suspension = Réponse libre depuis { $start } avec la masse suspendue à +{ $percent } %, nominale et à −{ $percent } %
uncertainty-band-rlc = Tension du condensateur depuis 1 V au coin de ζ minimal, au nominal et au coin de ζ maximal de la boîte de tolérances
uncertainty-ignored-rlc = Les curseurs du RLC sont ignorés.
uncertainty-ignored-suspension = Les curseurs de la suspension sont ignorés.
uncertainty-zeta-undefined = ζ n'est pas défini à une extrémité de l'intervalle
uncertainty-zeta-spans = ζ va de { $low } à { $high }
uncertainty-describe-band = { $what } : { $zeta } ; temps d'établissement à 5 % (croix) : { $first }, { $second } et { $third }. { $ignored }
uncertainty-dist-normal = normaux (tolérance = 3σ)
uncertainty-dist-uniform = uniformes
uncertainty-spec-zeta = La fenêtre de spécification de ζ, { $low }–{ $high }, est marquée ; { $share } des tirages respectent toute la spécification.
uncertainty-spec-settling-time = La limite de spécification, { $limit }, est marquée.
uncertainty-no-finite = Aucun tirage ne donne de valeur finie de la grandeur « { $quantity } ».
uncertainty-describe-histogram = Histogramme de la grandeur « { $quantity } » sur { $draws } tirages { $distribution } : de { $low } à { $high }, 5ᵉ centile { $p5 }, 95ᵉ centile { $p95 }.{ $marked ->
        [yes] {" "}{ $spec }
       *[no] {""}
    }
uncertainty-provisional-title = { $title } (provisoire)
uncertainty-provisional-description = Provisoire : d'après les { $shown } premiers tirages, tandis que le calcul de { $full } se poursuit. { $description }
uncertainty-axis-capacitor-voltage = tension du condensateur v_C
uncertainty-settling-band = bande d'établissement à 5 %
uncertainty-axis-draws = tirages
uncertainty-series-bins = tirages par classe ({ $bins } classes)
uncertainty-no-finite-values = aucune valeur finie
uncertainty-spec-limit = limite de spécification
uncertainty-percentiles = 5ᵉ / 95ᵉ centile
uncertainty-title = Analyse des tolérances
uncertainty-summary = Les composants réels n'ont pas exactement leur valeur nominale. Choisissez le système : le quart de véhicule (masse suspendue m, ressort k et amortisseur réglé pour ζ à la masse nominale ; la masse varie de ±dm selon la charge du véhicule) ou le circuit RLC série (R, L et C chacun à ±dR, ±dL, ±dC près). Seuls les curseurs du système choisi sont utilisés ; l'autre groupe est ignoré. Les intervalles exacts de ζ, ωₙ et Q sont obtenus aux coins de la boîte de tolérances. Le calcul de Monte-Carlo tire N conceptions (avec une graine : la même graine donne le même résultat), uniformes dans la tolérance ou normales avec la tolérance comme 3σ. Le rendement est la part des tirages dont ζ est dans la fenêtre de spécification et dont le temps d'établissement à 5 % (lâcher depuis le repos) ne dépasse pas la limite.
uncertainty-param-system = système
uncertainty-param-system-suspension = suspension de quart de véhicule
uncertainty-param-system-rlc = RLC série
uncertainty-param-m = suspension : masse suspendue
uncertainty-param-k = suspension : raideur du ressort
uncertainty-param-zeta = suspension : ζ de conception à la masse nominale
uncertainty-param-dm = suspension : tolérance sur la masse ±
uncertainty-param-R = RLC : résistance
uncertainty-param-L = RLC : inductance
uncertainty-param-C = RLC : capacité
uncertainty-param-dR = RLC : tolérance de la résistance ±
uncertainty-param-dL = RLC : tolérance de la bobine ±
uncertainty-param-dC = RLC : tolérance du condensateur ±
uncertainty-param-dist = distribution des composants
uncertainty-param-dist-uniform = uniforme dans ±tolérance
uncertainty-param-dist-normal = normale, tolérance = 3σ
uncertainty-param-N = tirages de Monte-Carlo
uncertainty-param-seed = graine aléatoire
uncertainty-param-zeta-lo = spécification : ζ minimal
uncertainty-param-zeta-hi = spécification : ζ maximal
uncertainty-param-ts-max = spécification : temps d'établissement maximal
uncertainty-param-hist = second histogramme
uncertainty-param-hist-zeta = taux d'amortissement ζ
uncertainty-param-hist-f0 = fréquence propre f0
uncertainty-param-hist-q = facteur de qualité Q
uncertainty-param-hist-bandwidth = bande passante
uncertainty-param-hist-settling-time = temps d'établissement
uncertainty-readout-zeta-min = ζ, minimum (exact)
uncertainty-readout-zeta-max = ζ, maximum (exact)
uncertainty-readout-wn-min = ωₙ, minimum (exact)
uncertainty-readout-wn-max = ωₙ, maximum (exact)
uncertainty-readout-Q-min = Q, minimum (exact)
uncertainty-readout-Q-max = Q, maximum (exact)
uncertainty-readout-yield = rendement (conforme à la spécification)
uncertainty-readout-zeta-p5 = ζ, 5ᵉ centile
uncertainty-readout-zeta-p95 = ζ, 95ᵉ centile
uncertainty-readout-Q-p5 = Q, 5ᵉ centile
uncertainty-readout-Q-p95 = Q, 95ᵉ centile
uncertainty-readout-draws = tirages
uncertainty-readout-compute-time = temps de calcul de Monte-Carlo
uncertainty-plot-band = Faisceau de réponses libres sur la tolérance
uncertainty-plot-zeta-hist = Monte-Carlo : taux d'amortissement ζ
uncertainty-plot-hist = Monte-Carlo : grandeur choisie
uncertainty-preset-1 = Conception ζ = 1 avec masse à ±10 %
uncertainty-preset-2 = Conception ζ = 0,7 avec masse à ±10 %
uncertainty-preset-3 = RLC, composants à 5 %
uncertainty-preset-4 = RLC, composants à 20 %
# Zeta Lab — français. Ids and variables as in en.ftl.

## La page

page-skip = Aller à la démonstration
page-demo = Démonstration
page-share = Partager / Intégrer
page-loading = Chargement du solveur…
page-footer = Zeta Lab — chaque nombre de cette page est calculé en Rust (compilé en WebAssembly) à partir de solutions exactes.
page-parameters = Paramètres
page-readouts = Résultats
page-about = À propos de cette démonstration
page-plot-in-view = Graphique affiché
page-presets = Préréglages
page-reset = Valeurs par défaut
page-exact-value = valeur exacte
page-export-group = Exporter { $plot }
page-download = Télécharger { $plot } en { $format }
page-play = Lecture
page-pause = Pause
page-sound-on = Son activé
page-sound-off = Son coupé
page-sound-hint = Écouter x(t) : la hauteur du son suit le déplacement
page-anim-time = Temps de l’animation
page-time-words = temps { $t } secondes
page-schematic = Schéma animé
page-dismiss = Fermer l’avis
page-failed = Une erreur s’est produite et la démonstration a été relancée : { $text }
page-no-demo = Il n’existe pas de démonstration « { $id } » ; affichage de { $fallback }.
page-no-wasm = Le solveur n’a pas pu être chargé ({ $text }). Cette page nécessite WebAssembly.
page-module-failed = Cette partie de la page n’a pas pu être chargée ({ $text }). Vérifiez la connexion et réessayez.
page-copy = Copier
page-equation = Équation
page-tour-head = L’article, figure par figure
page-tour-open = Ouvrir cet état dans la démonstration
page-tour-paper = L’article indique
page-tour-app = L’application calcule
page-tour-confirmed = Confirmé.
page-tour-differs = Diffère.
page-tour-pending = Vérification…
page-copied = Copié
page-copy-manual = Sélectionnez et copiez (Ctrl+C)
page-share-title = Partager ou intégrer « { $title } »
page-embed-view = {" "}Vue intégrée (sans en-tête du site)
page-autoplay = {" "}Lancer l’animation
page-theme = Thème{" "}
page-width = {" "}Largeur{" "}
page-height = {" "}Hauteur{" "}
page-sliders-shown = Curseurs affichés
page-sliders-locked = Curseurs verrouillés
page-plots-shown = Graphiques affichés
page-link = Lien
page-embed-code = Code d’intégration
page-preview = Aperçu de la démonstration intégrée
page-close = Fermer
page-language = Langue
page-language-nav = Langue
page-demos-nav = Démonstrations
page-no-script = Zeta Lab nécessite JavaScript et WebAssembly.
page-catalogue-failed = Le catalogue { $name } n’a pas pu être chargé ({ $text }) ; la page reste en anglais.
page-provisional = { $value } (provisoire)
page-study-progress = Calcul du résultat complet
page-readouts-shown = Résultats affichés
page-state-token = Jeton d’état
page-theme-auto = automatique
page-theme-light = clair
page-theme-dark = sombre
page-theme-projector = projecteur (contraste élevé)
page-share-visitor-language = langue du visiteur
page-share-language = {" "}Langue{" "}
page-share-fullscreen = {" "}Bouton plein écran
page-share-ranges = Plages et pas des curseurs (laisser vide pour garder ceux déclarés)
page-share-col-slider = curseur
page-share-col-from = de
page-share-col-to = à
page-share-col-step = pas
page-share-range-from = { $label } : minimum
page-share-range-to = { $label } : maximum
page-share-range-step = { $label } : pas
page-share-predict-task = Exercice de prédiction
page-share-none = aucun
page-share-predict = Les étudiants prédisent{" "}
page-share-predict-within = {" "}avec une tolérance de{" "}
page-share-presets = Préréglages de l’enseignant (inclus dans le lien)
page-share-preset-example = p. ex. Amortissement faible
page-share-preset-add = Ajouter les valeurs affichées
page-share-preset-format = Format : nom:clé=valeur,clé=valeur; autre nom:…
page-share-preset-default = Préréglage { $n }
page-share-preset-name = Nom{" "}
page-share-preset-list = Préréglages{" "}
page-lecturer-presets = Préréglages de l’enseignant
page-full-screen = Plein écran
page-exit-full-screen = Quitter le plein écran
page-no-stamp = Ce fichier ne contient aucune vue Zeta Lab (seuls les PNG, SVG et CSV exportés par Zeta Lab en contiennent).
page-token-invalid = Cette vue enregistrée n’est pas un jeton d’état Zeta Lab.
page-token-version = Cette vue enregistrée a la version de format « { $version } », que cette page ne sait pas lire ; rien n’a été modifié.
page-token-damaged = Cette vue enregistrée est endommagée et illisible ; rien n’a été modifié.
page-token-no-demo = Cette vue enregistrée désigne une démonstration que cette page n’a pas (« { $demo } ») ; rien n’a été modifié.
page-token-other-version-missing = Cette vue enregistrée provient d’une autre version de Zeta Lab : { $n ->
        [one] { $missing } n’y figure pas et prend la valeur par défaut.
       *[other] { $missing } n’y figurent pas et prennent la valeur par défaut.
    }
page-token-other-version-unknown = Cette vue enregistrée provient d’une autre version de Zeta Lab : { $m ->
        [one] { $unknown } est inconnu ici et a été ignoré.
       *[other] { $unknown } sont inconnus ici et ont été ignorés.
    }
page-token-other-version-both = Cette vue enregistrée provient d’une autre version de Zeta Lab : { $n ->
        [one] { $missing } n’y figure pas et prend la valeur par défaut
       *[other] { $missing } n’y figurent pas et prennent la valeur par défaut
    } ; { $m ->
        [one] { $unknown } est inconnu ici et a été ignoré.
       *[other] { $unknown } sont inconnus ici et ont été ignorés.
    }
page-predict-title = D’abord, prédire
page-predict-hint = Les graphiques et la grandeur « { $label } » restent masqués jusqu’à votre prédiction. Saisissez-la et appuyez sur Entrée.
page-predict-field = Votre prédiction de « { $label } »
page-predict-field-unit = Votre prédiction de « { $label } » ({ $unit })
page-predict-reveal = Révéler
page-predict-nan = « { $text } » n’est pas un nombre. Saisissez un nombre comme { $example }.
page-predict-undefined = « { $label } » n’est pas défini pour ces paramètres ; modifiez-les et réessayez.
page-predict-result-inside = Vous avez prédit { $p } ; « { $label } » vaut { $v } : { $how }, dans la tolérance de { $tol }.
page-predict-result-outside = Vous avez prédit { $p } ; « { $label } » vaut { $v } : { $how }, hors de la tolérance de { $tol }.
page-predict-exact = exactement juste
page-predict-high = trop élevée de { $d }
page-predict-low = trop basse de { $d }

## Graphiques

plot-clipped = tronqué : certaines valeurs dépassent les axes

## Mots partagés : axes, régimes

axis-time = temps t
axis-displacement = déplacement x
axis-extension = allongement x
axis-force = force F
axis-velocity = vitesse v
axis-real-part = partie réelle Re s
axis-imaginary-part = partie imaginaire Im s
regime-undamped = non amorti
regime-underdamped = sous-amorti
regime-critically-damped = amortissement critique
regime-overdamped = suramorti
regime-negatively-damped = amortissement négatif
regime-neutral = neutre
regime-divergent = divergent

## Démonstrations

## Le guide des enseignants (docs/embedding.md et docs/parameters.<tag>.md)

guide-parameters-heading = Paramètres de chaque démonstration
guide-parameters-note = Les paramètres d’URL de chaque démonstration, pour les liens et l’intégration (voir le guide, docs/embedding.md, en anglais). Généré à partir des déclarations Rust et du catalogue de cette langue ; un test échoue si cette liste et le code diffèrent.
guide-column-key = clé
guide-column-quantity = grandeur
guide-column-unit = unité
guide-column-range = plage
guide-column-default = valeur par défaut
guide-log = logarithmique
guide-readouts-plots = Résultats (`data-readout`) : { $readouts }. Graphiques (`plots=`) : { $plots }.

### design

design-map-title = { $metric ->
        [settling-time] Stabilisation à ±{ $band } de x₀
        [peak-rebound] Rebond maximal (% de x₀)
        [accel-rms] a_w (W_k)
       *[peak-transmissibility] Transmissibilité maximale |X/U|
    } : { $low } → { $high }
design-bar-label = { $metric ->
        [settling-time] temps d'établissement dans ±{ $band } de x₀ [s]
        [peak-rebound] rebond maximal [% de x₀]
        [accel-rms] a_w (RMS pondérée W_k) [m/s²]
       *[peak-transmissibility] transmissibilité maximale |X/U| [m/m]
    }{ $scale ->
        [log] , échelle log.
       *[linear] {""}
    }
design-axis-spring-rate = raideur du ressort k
design-axis-damper-rate = coefficient d'amortissement c
design-axis-settling-time = temps d'établissement dans ±{ $band } de x₀
design-axis-comfort = a_w (RMS pondérée W_k)
design-marker-selected = choisi
design-marker-settled = stabilisé
design-series-column = k = { $k }, c variable
design-series-pareto-front = front de Pareto
design-series-band = bande d'établissement ±{ $band } de x₀
design-series-fastest = le plus rapide de la grille
design-series-selected = réglage choisi
design-road = une route ISO 8608 de classe { $class } à { $speed }
design-with-road = { $value } (route de classe { $class }, { $speed })
design-grid-size = { $n } × { $n } = { $cells }
design-grid-size-provisional = { $n } × { $n } = { $cells } ({ $full } × { $full } en cours)
design-map-lowest = minimum { $value } en k = { $k }, c = { $c }
design-map-no-cell = aucune case n'est définie
design-map-selected-settles = le réglage choisi (ζ = { $zeta }) se stabilise dans ±{ $band } de x₀ en { $time }
design-map-selected-unsettled = le réglage choisi (ζ = { $zeta }) ne se stabilise pas
design-map-no-selection = aucun réglage valide choisi
design-describe-map = { $metric ->
        [settling-time] Temps d'établissement de la réponse libre depuis x₀ = { $x0 } dans ±{ $band } de x₀,
        [peak-rebound] Rebond maximal de la réponse libre depuis x₀ = { $x0 }, en % de x₀,
        [accel-rms] Confort a_w (accélération efficace de la caisse pondérée par W_k) du véhicule à deux degrés de liberté (roue de { $wheel }, pneu de { $tyre }), en régime stationnaire sur { $road },
       *[peak-transmissibility] Transmissibilité maximale |X/U|
    } pour k dans { $k_span } et c dans { $c_span } (grille de { $grid } × { $grid }, m = { $mass }) : { $lowest } ; { $selected }{ $outside ->
        [yes] {" "}(hors de la carte)
       *[no] {""}
    }. Couleurs du violet foncé ({ $low }) au jaune ({ $high }){ $scale ->
        [log] {" "}sur une échelle logarithmique
       *[linear] {""}
    }. Lignes iso-ζ en tirets pour ζ = { $z1 } ; { $z2 } ; { $z3 } ; { $z4 } et { $z5 } ; × marque la case minimale, ● le réglage choisi.
design-describe-pareto = Front de Pareto de { $count ->
        [one] { $count } réglage non dominé
       *[other] { $count } réglages non dominés
    } : du plus rapide, qui se stabilise dans ±{ $band } de x₀ en { $fast_time } avec a_w = { $fast_accel }, au plus confortable, { $smooth_time } avec a_w = { $smooth_accel }. { $selected } Confort a_w : accélération efficace de la caisse pondérée par W_k, pour le véhicule à deux degrés de liberté sur { $road }.
design-pareto-selected = Le réglage choisi se stabilise dans ±{ $band } de x₀ en { $time } avec a_w = { $accel }.
design-pareto-selected-unsettled = Le réglage choisi n'a pas de temps d'établissement.
design-pareto-empty = Aucun réglage de la grille n'a à la fois un temps d'établissement et une valeur de confort a_w.
design-describe-response = Réglage choisi (ζ = { $zeta }) lâché sans vitesse depuis x₀ = { $x0 } (réponse libre, pas une réponse indicielle) : rebondit de { $rebound } de x₀ et reste dans ±{ $band } de x₀ après { $time }.
design-describe-response-fastest = Réglage choisi (ζ = { $zeta }) lâché sans vitesse depuis x₀ = { $x0 } (réponse libre, pas une réponse indicielle) : rebondit de { $rebound } de x₀ et reste dans ±{ $band } de x₀ après { $time } ; le réglage le plus rapide de la grille (k = { $k }, c = { $c }) se stabilise en { $fastest_time }.
design-response-unsettled = Le réglage choisi ne se stabilise pas.
design-provisional = Provisoire : d'après une grille grossière de { $coarse } × { $coarse }, pendant le calcul du balayage de { $full } × { $full }. { $description }
design-title = Espace de conception (k, c)
design-summary = Chaque case de la carte est un quart de véhicule (masse suspendue m sur un ressort k et un amortisseur c), colorée selon l'indicateur choisi : temps d'établissement et rebond maximal de la réponse libre lâchée sans vitesse depuis x₀ = 60 mm (pas une réponse indicielle : la bande et le rebond sont rapportés à x₀), transmissibilité maximale, ou confort vibratoire tel que le mesure l'ISO 2631-1 : a_w, l'accélération efficace (RMS) de la caisse pondérée par le filtre W_k (la sensibilité d'une personne assise à chaque fréquence), en régime stationnaire sur une route aléatoire ISO 8608 à la vitesse V. Pour le confort, chaque case est le véhicule à deux degrés de liberté (cette caisse sur la roue m_u et le pneu k_t réglés plus bas, via l'équation de Lyapunov) : les mêmes valeurs que la démo quarter-car-2dof pour le même véhicule ; les résultats donnent aussi la valeur efficace non pondérée. Les lignes en tirets relient les réglages de même taux d'amortissement ζ = c/(2√(km)). Le front de Pareto réunit les réglages qu'aucun autre ne surpasse à la fois en confort et en stabilisation. Cliquez sur la carte (ou sur un point du front) pour choisir un réglage ; déplacez la masse pour voir toute la carte se décaler.
design-param-m = masse suspendue
design-param-mu = confort : masse de la roue (non suspendue)
design-param-kt = confort : raideur du pneu
design-param-metric = indicateur de la carte
design-param-metric-settling-time = temps d'établissement (réponse libre)
design-param-metric-peak-rebound = rebond maximal (réponse libre)
design-param-metric-accel-rms = confort a_w (accélération efficace de la caisse pondérée par W_k)
design-param-metric-peak-transmissibility = transmissibilité maximale |X/U|
design-param-band = bande d'établissement, ± % de x₀ (réponse libre)
design-param-road = route (ISO 8608)
design-param-road-a = classe A (très bonne)
design-param-road-b = classe B (bonne)
design-param-road-c = classe C (moyenne)
design-param-road-d = classe D (mauvaise)
design-param-V = confort : vitesse
design-param-k-min = carte : raideur de ressort minimale
design-param-k-max = carte : raideur de ressort maximale
design-param-c-min = carte : coefficient d'amortissement minimal
design-param-c-max = carte : coefficient d'amortissement maximal
design-param-k = raideur de ressort choisie
design-param-c = coefficient d'amortissement choisi
design-param-n = cases de la grille par axe
design-readout-k = raideur de ressort choisie k
design-readout-c = coefficient d'amortissement choisi c
design-readout-zeta = taux d'amortissement ζ
design-readout-settling-time = temps d'établissement dans la bande ± de x₀ (réponse libre)
design-readout-overshoot = rebond maximal, % de x₀ (réponse libre)
design-readout-accel-rms = a_w : accélération efficace de la caisse pondérée par W_k de l'ISO 2631-1 (véhicule à deux degrés de liberté, en régime stationnaire sur la route ISO 8608 à la vitesse V)
design-readout-accel-unweighted = accélération efficace de la caisse, non pondérée (même véhicule, même route)
design-readout-grid-size = taille de la grille (cases)
design-readout-compute-time = durée de calcul du balayage
design-plot-map = Indicateur sur (k, c) avec lignes iso-ζ
design-plot-pareto = Confort et stabilisation : front de Pareto
design-plot-response = Réglage choisi : réponse libre x(t)
design-preset-1 = Carte du temps d'établissement, 300 kg, ζ ≈ 0,37
design-preset-2 = Véhicule chargé à 500 kg, mêmes composants
design-preset-3 = Carte de confort sur une route de classe C
design-preset-4 = Carte du rebond maximal, réglage à ζ = 0,7
design-preset-5 = Grille fine de 160 × 160

## Avis (une valeur de paramètre inutilisable)

notice-value = { $problem ->
        [toggle] { $label } ({ $key }) : « { $value } » n’est ni activé ni désactivé ; valeur par défaut utilisée.
        [option] { $label } ({ $key }) : « { $value } » ne fait pas partie de { $options } ; valeur par défaut utilisée.
        [number] { $label } ({ $key }) : « { $value } » n’est pas un nombre ; valeur par défaut { $default } utilisée.
        [range-empty] { $label } ({ $key }) : la plage « { $value } » est vide dans { $min } … { $max } ; plage complète conservée.
        [range-not-two-numbers] { $label } ({ $key }) : la plage « { $value } » n’est pas deux nombres « bas,haut » ; plage complète conservée.
        [step] { $label } ({ $key }) : le pas « { $value } » n’est pas un nombre entre 0 et { $span } ; { $step } conservé.
       *[range] { $label } ({ $key }) = { $value } est hors de { $min } … { $max }{ $unit } ; { $used } utilisé.
    }

## Fichiers exportés

export-csv-heading = Zeta Lab, démonstration { $demo } : { $title }
export-series = série { $n }

