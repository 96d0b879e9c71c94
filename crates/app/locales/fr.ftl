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

