
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
