
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
flutter-series-box = caisson profilé (approx. pédagogique)
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
        [h] la section en H de 1940
        [box] le caisson profilé
       *[simplest] le modèle le plus simple
    } (approximation pédagogique, pas des valeurs mesurées) : la rotation croît là où A₂* dépasse 4Iζ_s/(ρB⁴).
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
flutter-summary = Un vent constant peut fournir de l'énergie à un tablier de pont en torsion par l'intermédiaire de son propre mouvement. Scanlan a écrit le moment du vent sur un tablier en torsion à l'aide de dérivées de flottement mesurées en soufflerie : A₂* multiplie la vitesse de rotation (un terme d'amortissement) et A₃* la rotation (un terme de raideur), toutes deux fonctions de la fréquence réduite K = Bω/U. Le taux d'amortissement du tablier devient ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I) : pour la section en H non profilée du tablier de Tacoma de 1940, A₂* change de signe quand le vent forcit, et dès qu'il dépasse le seuil 4Iζ_s/(ρB⁴), toute petite rotation croît à la fréquence de torsion propre du tablier (près de 0,2 Hz) — c'est du flottement, pas de la résonance : un vent constant n'a aucune fréquence à laquelle s'accorder, le mouvement crée sa propre excitation. La fréquence est obtenue par itération à chaque vitesse de vent, puisque K en dépend. La théorie linéaire laisse la rotation croître indéfiniment ; ici, on suppose que le terme d'amortissement du vent est divisé par deux pour une rotation θ_s, ce qui borne le mouvement sur un grand cycle limite, comme le 7 novembre 1940, quand, par un vent d'environ 42 mph, la rotation a crû en moins d'une heure jusqu'à la rupture du tablier. Approximations pédagogiques, présentées comme telles : A₂* et A₃* sont des courbes lisses ayant l'allure des résultats publiés pour la section en H et pour des sections proches d'un profil d'aile (Scanlan et Tomko 1971 ; Billah et Scanlan 1991), et non des valeurs relevées dans ces travaux ; I, ζ_s et θ_s sont supposés. Un caisson profilé, dont l'A₂* reste négatif, n'entre jamais en flottement dans cette plage. Le modèle le plus simple ζ_eff = ζ_s − g·U est conservé pour comparaison.
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
